// Uploads the frame's constants into a uniform buffer with vkCmdUpdateBuffer, as a
// transfer pass of the graph, so every reader gets its barrier from the graph.
// Publishes keys::kFrameConstants.
#pragma once

#include "engine/framegraph/frame_graph.hpp"
#include "engine/render/frame_constants.hpp"

namespace vkw::passes {

void add_frame_constants_upload(fg::FrameGraph& graph, const FrameConstants& constants);

}  // namespace vkw::passes
