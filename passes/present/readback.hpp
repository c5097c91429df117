// Copies an image or a buffer into a host-visible buffer owned by the caller (imported
// into the graph, handed back in the host-read state) and requests it as the graph's
// output. `name` names both the pass and the imported buffer; a graph that reads back
// several results gives each its own.
#pragma once

#include "engine/framegraph/frame_graph.hpp"

#include <string>

namespace vkw::passes {

void add_readback_pass(fg::FrameGraph& graph, fg::ImageHandle image, VkBuffer host_buffer, VkDeviceSize bytes,
                       const std::string& name = "readback");
void add_readback_pass(fg::FrameGraph& graph, fg::BufferHandle buffer, VkBuffer host_buffer, VkDeviceSize bytes,
                       const std::string& name = "readback");

}  // namespace vkw::passes
