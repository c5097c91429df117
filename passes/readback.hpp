// Copies an image or a buffer into a host-visible buffer owned by the caller (imported
// into the graph, handed back in the host-read state) and requests it as the graph's
// output.
#pragma once

#include "engine/framegraph/frame_graph.hpp"

namespace vkw::passes {

void add_readback_pass(fg::FrameGraph& graph, fg::ImageHandle image, VkBuffer host_buffer, VkDeviceSize bytes);
void add_readback_pass(fg::FrameGraph& graph, fg::BufferHandle buffer, VkBuffer host_buffer, VkDeviceSize bytes);

}  // namespace vkw::passes
