// The window's user interface (Dear ImGui panels and the statistics overlay) drawn over the
// displayed frame. The caller's `record` records the draw calls; the pass loads the target and
// always records inside a VkRenderPass object, whatever the graph's default, because Debian's
// Dear ImGui 1.86 has no dynamic-rendering path in its Vulkan backend: its pipeline is made
// for a VkRenderPass (FrameExecutor::render_pass of this pass, or any compatible one).
#pragma once

#include "engine/framegraph/frame_graph.hpp"

#include <functional>

namespace vkw::passes {

inline constexpr const char* kPresentOverlayPass = "present overlay";

// Returns the target's new version.
[[nodiscard]] fg::ImageHandle add_present_overlay_pass(fg::FrameGraph& graph, fg::ImageHandle target,
                                                       std::function<void(VkCommandBuffer)> record);

}  // namespace vkw::passes
