// add_present_overlay_pass (present_overlay.hpp).
#include "passes/present/present_overlay.hpp"

#include "engine/framegraph/pass_context.hpp"

namespace vkw::passes {

fg::ImageHandle add_present_overlay_pass(fg::FrameGraph& graph, fg::ImageHandle target,
                                         std::function<void(VkCommandBuffer)> record) {
    struct Data {
        fg::ImageHandle target;
    };
    const auto& data = graph.add_pass<Data>(
        kPresentOverlayPass, fg::PassKind::Graphics,
        [&](fg::PassBuilder& builder, Data& d) {
            d.target = builder.color_attachment(target, fg::LoadOp::Load);  // blended over the frame
            builder.record_with(fg::RecordingKind::RenderPassObject);
        },
        [record = std::move(record)](const Data&, fg::PassContext& context) { record(context.cmd()); });
    return data.target;
}

}  // namespace vkw::passes
