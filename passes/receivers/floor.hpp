// The floor plane as a Lambertian receiver, drawn over the sky with a depth buffer
// (reversed-Z), lit above or below the water (shaders/receivers/receiver.frag). Reads the
// scene optics; reads and republishes keys::kHdrColor; publishes keys::kSceneDepth. Reads
// keys::kCameraMedium, the camera-medium split's per-pixel medium, when it was published before.
#pragma once

#include "engine/framegraph/frame_graph.hpp"

namespace vkw::passes {

// caustic_layer: also create and write the caustic layer (passes/caustics/caustic_layer.hpp).
void add_floor_pass(fg::FrameGraph& graph, bool caustic_layer = false);

}  // namespace vkw::passes
