// add_present_handoff_pass (present_handoff.hpp).
#include "passes/present/present_handoff.hpp"

#include "engine/framegraph/pass_context.hpp"

namespace vkw::passes {

fg::AccessState present_handoff_final_state() { return fg::access_state(fg::Use::SampledRead, fg::PassKind::Graphics); }

void add_present_handoff_pass(fg::FrameGraph& graph, fg::ImageHandle hdr, const fg::ImportedImage& target) {
    fg::ImportedImage imported = target;
    imported.initial = {};  // overwritten whole: nothing of the last frame is kept
    imported.final_state = present_handoff_final_state();
    const fg::ImageHandle window_hdr = graph.import_image("window HDR", imported);
    struct Data {
        fg::ImageHandle source;
        fg::ImageHandle target;
    };
    const auto& data = graph.add_pass<Data>(
        "present handoff", fg::PassKind::Transfer,
        [&](fg::PassBuilder& builder, Data& d) {
            d.source = builder.copy_source(hdr);
            d.target = builder.copy_destination(window_hdr);
        },
        [](const Data& d, fg::PassContext& context) {
            const VkExtent2D extent = context.extent(d.source);
            VkImageCopy region{};
            region.srcSubresource = region.dstSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
            region.extent = {extent.width, extent.height, 1};
            vkCmdCopyImage(context.cmd(), context.image(d.source), VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL,
                           context.image(d.target), VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 1, &region);
        });
    graph.request_output(data.target);
}

}  // namespace vkw::passes
