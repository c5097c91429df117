// add_whole_image_copy_pass (whole_image_copy.hpp).
#include "passes/common/whole_image_copy.hpp"

#include "engine/framegraph/pass_context.hpp"

namespace vkw::passes {

void add_whole_image_copy_pass(fg::FrameGraph& graph, const std::string& name, fg::ImageHandle source,
                               fg::ImageHandle target) {
    struct Data {
        fg::ImageHandle source, target;
    };
    const auto& data = graph.add_pass<Data>(
        name, fg::PassKind::Transfer,
        [&](fg::PassBuilder& builder, Data& d) {
            d.source = builder.copy_source(source);
            d.target = builder.copy_destination(target);
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
