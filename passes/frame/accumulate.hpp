// The running sum of a box-filtered frame's sub-frames on the device, for a caller that shows the
// frame instead of reading it back (the window): each sub-frame's colour is added into an image
// that outlives the sub-frame's graph, and the last sub-frame leaves the mean there, equal to what
// render_filtered (passes/frame/supersampled_frame.hpp) averages on the CPU.
#pragma once

#include "engine/framegraph/frame_graph.hpp"

#include <cstdint>

namespace vkw::passes {

// The usage the sum's image needs: written and read by the accumulation, then copied out.
inline constexpr VkImageUsageFlags kSubFrameSumUsage = VK_IMAGE_USAGE_STORAGE_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT;

// Adds sub-frame `index` of `count` (`colour`, RGBA32F) into `sum`: an R32G32B32A32_SFLOAT image of
// the colour's size with kSubFrameSumUsage, owned by the caller and imported here in the state the
// previous sub-frame left it in. Returns the sum's handle after the pass: the mean after the last
// sub-frame.
fg::ImageHandle add_sub_frame_accumulation(fg::FrameGraph& graph, fg::ImageHandle colour, fg::ImportedImage sum,
                                           uint32_t index, uint32_t count);

}  // namespace vkw::passes
