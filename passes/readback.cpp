#include "passes/readback.hpp"

#include "engine/framegraph/pass_context.hpp"

namespace vkw::passes {

void add_readback_pass(fg::FrameGraph& graph, fg::ImageHandle image, VkBuffer host_buffer, VkDeviceSize bytes) {
    fg::ImportedBuffer imported{host_buffer, bytes};
    imported.final_state = fg::access_state(fg::Use::HostRead, fg::PassKind::Transfer);
    const fg::BufferHandle target = graph.import_buffer("readback", imported);
    struct Data {
        fg::ImageHandle source;
        fg::BufferHandle target;
    };
    const auto& data = graph.add_pass<Data>(
        "readback", fg::PassKind::Transfer,
        [&](fg::PassBuilder& builder, Data& d) {
            d.source = builder.copy_source(image);
            d.target = builder.copy_destination(target);
        },
        [](const Data& d, fg::PassContext& context) {
            const VkExtent2D extent = context.extent(d.source);
            VkBufferImageCopy region{};
            region.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
            region.imageExtent = {extent.width, extent.height, 1};
            vkCmdCopyImageToBuffer(context.cmd(), context.image(d.source), VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL,
                                   context.buffer(d.target), 1, &region);
        });
    graph.request_output(data.target);
}

}  // namespace vkw::passes
