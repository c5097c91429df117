// A box-filtered frame (engine/scene/pixel_filter.hpp): k^2 sub-frames of the renderer, each with
// the camera's image plane shifted by one stratum's centre for every pixel, averaged in float.
// Every pass runs in every sub-frame, the light-space ones (surface, photons, map, resolve)
// included, and the frame's time is the sum of the sub-frames' (each pass's too). A point filter
// is one plain render, bit-identical to Renderer::render.
#pragma once

#include "engine/scene/pixel_filter.hpp"
#include "passes/frame/renderer.hpp"

#include <cstdint>
#include <functional>

namespace vkw {

// `after_sub_frame`, if given, is called with the number of sub-frames done after each one (a
// command's progress report).
RenderResult render_filtered(Renderer& renderer, const Scene& scene, const RenderOptions& options,
                             const PixelFilter& filter,
                             const std::function<void(uint32_t done)>& after_sub_frame = nullptr);

}  // namespace vkw
