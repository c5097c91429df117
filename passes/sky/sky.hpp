// The sky seen directly: constant radiance plus the sun's disk, written into a new
// HDR colour target that the later passes draw over. Publishes keys::kHdrColor.
#pragma once

#include "engine/framegraph/frame_graph.hpp"

namespace vkw::passes {

void add_sky_pass(fg::FrameGraph& graph);

}  // namespace vkw::passes
