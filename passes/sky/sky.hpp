// The sky seen directly: constant radiance plus the sun's disk, written into a new
// HDR colour target that the later passes draw over. Publishes keys::kHdrColor.
// `infinite_water`: the scene's water has no edge, so a camera ray in it that meets nothing runs
// to its bottom and brings the sun's in-scatter (reads keys::kSceneOptics); else such a ray sees
// nothing.
#pragma once

#include "engine/framegraph/frame_graph.hpp"

namespace vkw::passes {

void add_sky_pass(fg::FrameGraph& graph, bool infinite_water);

}  // namespace vkw::passes
