// The sky seen directly: constant radiance plus the sun's disk. Drawn after the opaque passes
// (the water, the floor, the receiver meshes), over only the pixels they left at the far plane: a
// read-only depth test against the scene depth, so no pixel is shaded twice. Without an opaque pass
// it creates the HDR colour target and writes every pixel. Publishes keys::kHdrColor.
// `infinite_water`: the scene's water has no edge, so a camera ray in it that meets nothing runs
// to its bottom and brings the sun's in-scatter (reads keys::kSceneOptics); else such a ray sees
// nothing.
#pragma once

#include "engine/framegraph/frame_graph.hpp"

namespace vkw::passes {

void add_sky_pass(fg::FrameGraph& graph, bool infinite_water);

}  // namespace vkw::passes
