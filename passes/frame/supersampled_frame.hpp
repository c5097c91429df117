// A box-filtered frame (engine/scene/pixel_filter.hpp): k^2 sub-frames of the renderer, each with
// the camera's image plane shifted by one stratum's centre for every pixel, averaged in float.
// Every pass runs in every sub-frame, the light-space ones (surface, photons, map, resolve)
// included, and the frame's time is the sum of the sub-frames' (each pass's too). A point filter
// is one plain render, bit-identical to Renderer::render.
#pragma once

#include "engine/scene/pixel_filter.hpp"
#include "passes/frame/renderer.hpp"

namespace vkw {

RenderResult render_filtered(Renderer& renderer, const Scene& scene, const RenderOptions& options,
                             const PixelFilter& filter);

}  // namespace vkw
