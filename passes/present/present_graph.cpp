#include "passes/present/present_graph.hpp"

#include "engine/core/errors.hpp"
#include "passes/present/present_handoff.hpp"
#include "passes/present/present_overlay.hpp"
#include "passes/present/readback.hpp"

namespace vkw::window {

PresentGraph::PresentGraph(Context& context, fg::PipelineStore& pipelines, const PresentImages& images,
                           const passes::PresentTonemapSettings* settings, std::function<void(VkCommandBuffer)> overlay,
                           VkBuffer readback) {
    graph_ = std::make_unique<fg::FrameGraph>();
    graph_->set_default_recording(fg::RecordingKind::RenderPassObject);

    fg::ImportedImage hdr = images.hdr;
    hdr.initial = passes::present_handoff_final_state();
    const fg::ImageHandle window_hdr = graph_->import_image("window HDR", hdr);

    fg::ImportedImage swapchain;
    swapchain.image = images.swapchain_image;
    swapchain.view = images.swapchain_view;
    swapchain.width = hdr.width;
    swapchain.height = hdr.height;
    swapchain.format = images.swapchain_format;
    // Acquired images hold nothing we keep; the submission waits for the acquire semaphore in
    // the colour-output stage, where the first barrier's source scope begins.
    swapchain.initial = {VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT, VK_ACCESS_2_NONE, VK_IMAGE_LAYOUT_UNDEFINED};
    swapchain.final_state = fg::AccessState{VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT, VK_ACCESS_2_NONE,
                                            VK_IMAGE_LAYOUT_PRESENT_SRC_KHR};
    fg::ImageHandle target = graph_->import_image("swapchain image", swapchain);

    if (readback) {
        const VkDeviceSize bytes = VkDeviceSize{hdr.width} * hdr.height * 4 * sizeof(float);
        passes::add_readback_pass(*graph_, window_hdr, readback, bytes, "screenshot readback");
    }
    target = passes::add_present_tonemap_pass(*graph_, window_hdr, target, settings);
    target = passes::add_present_overlay_pass(*graph_, target, std::move(overlay));
    graph_->request_output(target);
    graph_->compile(hdr.width, hdr.height);
    executor_ = std::make_unique<fg::FrameExecutor>(context, *graph_, pipelines,
                                                    fg::ExecutorOptions{false, fg::TimingMode::None});
}

VkRenderPass PresentGraph::overlay_render_pass() const {
    for (uint32_t pass = 0; pass < graph_->passes().size(); ++pass) {
        if (graph_->passes()[pass].name == passes::kPresentOverlayPass) return executor_->render_pass(pass);
    }
    throw InternalError("present graph: no '" + std::string(passes::kPresentOverlayPass) + "' pass");
}

}  // namespace vkw::window
