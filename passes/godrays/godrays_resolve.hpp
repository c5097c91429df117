// The godray radiance pyramids of add_godray_lines_passes turned into an RGBA32F image at the
// godray resolution (shaders/godrays/godray_resolve.comp): every level upsampled bilinearly and
// summed, times the LSB, the flat beam's phase function and the surface's weight (R, T / n^2) for
// each pixel's own view direction; the pixel's camera medium (add_godray_depth_pass) picks the
// views.
#pragma once

#include "engine/framegraph/frame_graph.hpp"

#include <cstdint>

namespace vkw::passes {

// `radiance` is the pyramid of a width x height godray image at `scale` of the output
// (add_godray_lines_passes). Reads the frame constants (the LSB is derived from them). Serves
// VolumeCaustics.
fg::ImageHandle add_godray_resolve_pass(fg::FrameGraph& graph, fg::BufferHandle radiance, fg::ImageHandle view_depth,
                                        float scale, uint32_t width, uint32_t height);

}  // namespace vkw::passes
