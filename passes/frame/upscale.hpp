// The frame's resolution scale: the scene's passes render at a fraction of the output size per
// side (RenderOptions::render_scale), and this pass stretches their image to the output size with
// the bilinear filter, before the readback or the window's hand-off. It is the cheapest way to
// trade pixels for time, and the budget's coarsest knob (tools/vkwater/budget/): every
// per-pixel pass costs the square of the scale. The filter is exact for radiance that varies
// linearly over two source pixels and blurs what varies faster; docs/accuracy.md measures it.
// Shader: shaders/frame/upscale.frag.
#pragma once

#include "engine/framegraph/frame_graph.hpp"

#include <cstdint>
#include <string>

namespace vkw::passes {

// `source` (any size) stretched over a new R32G32B32A32_SFLOAT image of width x height: each output
// pixel centre maps to the same fraction of the source and reads it with the bilinear filter,
// clamped at the edges. Returns the new image.
[[nodiscard]] fg::ImageHandle add_upscale_pass(fg::FrameGraph& graph, fg::ImageHandle source, uint32_t width,
                                               uint32_t height, const std::string& name);

// The size the scene's passes render at for an output of `output` pixels along one side: the
// output times the scale, rounded, at least 1.
uint32_t scaled_size(uint32_t output, double render_scale);

}  // namespace vkw::passes
