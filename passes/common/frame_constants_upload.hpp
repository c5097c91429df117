// Uploads the frame's constants into a uniform buffer with vkCmdUpdateBuffer, as a
// transfer pass of the graph, so every reader gets its barrier from the graph.
// `constants` is read when the pass records, not when it is declared: a compiled graph
// is reused frame after frame while its owner updates the values in place.
// Publishes keys::kFrameConstants.
#pragma once

#include "engine/framegraph/frame_graph.hpp"
#include "passes/common/frame_constants.hpp"

namespace vkw::passes {

void add_frame_constants_upload(fg::FrameGraph& graph, const FrameConstants* constants);

}  // namespace vkw::passes
