// A box-filtered frame (engine/scene/pixel_filter.hpp): k^2 sub-frames of the renderer, each with
// the camera's image plane shifted by one stratum's centre for every pixel, averaged in float.
// The light-space caustic map does not depend on the shift: the first sub-frame makes it for the
// cameras of all of them and keeps it, and the others read it (RenderOptions::caustic_map_carry),
// so the photons are traced once per frame. Every pixel the others read in it holds what their own
// map would (the photon culling keeps every photon that can reach a texel any of them reads), so
// the image is bit-identical to k^2 independent sub-frames. The frame's time is the sum of the
// sub-frames' (each pass's too, by name). A point filter is one plain render, bit-identical to
// Renderer::render.
#pragma once

#include "engine/scene/pixel_filter.hpp"
#include "passes/frame/renderer.hpp"

#include <cstdint>
#include <functional>
#include <vector>

namespace vkw {

// The image-plane shifts (Camera::image_shift_ndc) of the filter's sub-frames at width x height.
std::vector<glm::dvec2> sub_frame_shifts(const PixelFilter& filter, uint32_t width, uint32_t height);

// Adds a sub-frame's pass times to the frame's, by pass name (the later sub-frames leave out the
// caustic map's passes), and its total.
void add_sub_frame_times(fg::FrameReport& sum, const fg::FrameReport& sub);

// `after_sub_frame`, if given, is called with the number of sub-frames done after each one (a
// command's progress report).
RenderResult render_filtered(Renderer& renderer, const Scene& scene, const RenderOptions& options,
                             const PixelFilter& filter,
                             const std::function<void(uint32_t done)>& after_sub_frame = nullptr);

}  // namespace vkw
