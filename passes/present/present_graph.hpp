// The window's present graph, one per swapchain image: the hand-off HDR image (imported in the
// state passes/present_handoff leaves it) tonemapped into swapchain image i (imported
// UNDEFINED in the colour-output stage that the acquire semaphore is waited in, and left
// PRESENT_SRC), the user interface drawn over it, and, on screenshot frames, the HDR image
// read back to the host before that. It records into the frame's command buffer after the
// scene graph, in the same submission, so synchronization validation sees the hand-off
// whole; graphics passes record with VkRenderPass objects, whose attachments Debian's
// synchronization validation checks (it does not check dynamic rendering's).
//
// One graph per image because the frame graph makes its framebuffers from the imported
// views when it compiles; none of them owns a transient resource, so they cost little.
#pragma once

#include "engine/framegraph/executor.hpp"
#include "engine/framegraph/frame_graph.hpp"
#include "passes/present/present_tonemap.hpp"

#include <functional>
#include <memory>

namespace vkw::window {

struct PresentImages {
    fg::ImportedImage hdr;  // the hand-off image: R32G32B32A32_SFLOAT, the swapchain's size
    VkImage swapchain_image = VK_NULL_HANDLE;
    VkImageView swapchain_view = VK_NULL_HANDLE;
    VkFormat swapchain_format = VK_FORMAT_UNDEFINED;
};

class PresentGraph {
public:
    // `readback`: a host-visible buffer of width x height x 16 bytes that receives the HDR
    // image, or VK_NULL_HANDLE. `settings` and `overlay` are used when the graph records.
    PresentGraph(Context& context, fg::PipelineStore& pipelines, const PresentImages& images,
                 const passes::PresentTonemapSettings* settings, std::function<void(VkCommandBuffer)> overlay,
                 VkBuffer readback = VK_NULL_HANDLE);

    void record(VkCommandBuffer cmd) { executor_->record(cmd); }
    // The overlay pass's render pass, for Dear ImGui's pipeline (ImGuiLayer::connect).
    VkRenderPass overlay_render_pass() const;
    const fg::FrameGraph& graph() const { return *graph_; }

private:
    std::unique_ptr<fg::FrameGraph> graph_;
    std::unique_ptr<fg::FrameExecutor> executor_;  // after graph_: destroyed first
};

}  // namespace vkw::window
