// The frame's scene depth (keys::kSceneDepth: D32, reverse Z, cleared to 0) as a drawing pass's
// depth attachment. The first opaque pass of the frame creates and clears it and the later ones
// load it, so the passes can draw in whatever order culls the most: the water goes before the floor,
// and the floor's pixels behind the surface then fail the depth test before they are shaded.
#pragma once

#include "engine/framegraph/blackboard.hpp"
#include "engine/framegraph/frame_graph.hpp"

namespace vkw::passes {

fg::ImageHandle scene_depth_attachment(fg::PassBuilder& builder, const fg::Blackboard& blackboard);

}  // namespace vkw::passes
