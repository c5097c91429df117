// The floor plane as a Lambertian receiver, drawn over the sky with a depth buffer
// (reversed-Z). Reads and republishes keys::kHdrColor; publishes keys::kSceneDepth.
#pragma once

#include "engine/framegraph/frame_graph.hpp"

namespace vkw::passes {

void add_floor_pass(fg::FrameGraph& graph);

}  // namespace vkw::passes
