// A transfer pass that copies the whole of one image into another of the same size and format,
// for handing a frame's result to an image the graph imports (so that it outlives the graph):
// the window's hand-off of the HDR colour, the caustic map kept between sub-frames.
#pragma once

#include "engine/framegraph/frame_graph.hpp"

#include <string>

namespace vkw::passes {

// Copies `source` into `target` and requests `target` as an output of the graph (nothing else
// reads it in this frame).
void add_whole_image_copy_pass(fg::FrameGraph& graph, const std::string& name, fg::ImageHandle source,
                               fg::ImageHandle target);

}  // namespace vkw::passes
