// The frame's shared opaque targets as a drawing pass's attachments: the scene depth
// (keys::kSceneDepth: D32, reverse Z, cleared to 0) and the HDR colour (keys::kHdrColor: RGBA32F,
// radiance). The first opaque pass of the frame creates them and the later ones load them, so the
// passes can draw in whatever order culls the most: the water goes before the floor, whose pixels
// behind the surface then fail the depth test before they are shaded, and the sky goes last, over
// only the pixels that nothing else covered (passes/sky/sky.hpp).
#pragma once

#include "engine/framegraph/blackboard.hpp"
#include "engine/framegraph/frame_graph.hpp"

namespace vkw::passes {

fg::ImageHandle scene_depth_attachment(fg::PassBuilder& builder, const fg::Blackboard& blackboard);

// The HDR colour: loaded where an earlier pass made it, else created and cleared to 0 (each pixel
// is then written by the opaque pass that covers it, or by the sky).
fg::ImageHandle hdr_colour_attachment(fg::PassBuilder& builder, const fg::Blackboard& blackboard);

}  // namespace vkw::passes
