// The scene at the godray resolution: per godray pixel, the distance along its
// ray to the farthest scene surface among the output pixels it covers, and whether the camera ray
// starts in the water (shaders/godrays/godray_depth.comp). The lines test beam points against it,
// the blur and the upsampling keep to one surface with it, and the marched baseline ends its
// view segments on it.
#pragma once

#include "engine/framegraph/frame_graph.hpp"

namespace vkw::passes {

// RGBA32F at `scale` of the output (r: distance, m, 1e20 where the ray meets nothing; g: 1 in the
// water). Reads the frame constants, the scene depth and, when the stencil split published it, the
// camera medium mask. Serves VolumeCaustics.
fg::ImageHandle add_godray_depth_pass(fg::FrameGraph& graph, float scale);

}  // namespace vkw::passes
