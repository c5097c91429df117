// The water surface drawn over the scene and shaded with the simplest correct lookups
// (shaders/water_shading/water_surface.frag): Fresnel, the sky in reflection, the
// floor through refraction, the medium along every path, from above and from below.
// Reads the surface grid of passes/water_surface.hpp and, when the stencil split published it
// before, keys::kCameraMedium (per-pixel camera medium); serves Effect::Water.
#pragma once

#include "engine/framegraph/frame_graph.hpp"

namespace vkw::passes {

void add_water_shading_pass(fg::FrameGraph& graph, fg::BufferHandle surface, uint32_t grid_resolution);

}  // namespace vkw::passes
