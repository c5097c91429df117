#include "passes/present/readback.hpp"

#include "engine/framegraph/pass_context.hpp"

namespace vkw::passes {
namespace {

// The pass both overloads add: `Source` is the handle type, `copy` records the command.
template <class Source, class Copy>
void add_copy_to_host(fg::FrameGraph& graph, Source source, VkBuffer host_buffer, VkDeviceSize bytes,
                      const std::string& name, Copy copy) {
    fg::ImportedBuffer imported{host_buffer, bytes};
    imported.final_state = fg::access_state(fg::Use::HostRead, fg::PassKind::Transfer);
    const fg::BufferHandle target = graph.import_buffer(name, imported);
    struct Data {
        Source source;
        fg::BufferHandle target;
    };
    const auto& data = graph.add_pass<Data>(
        name, fg::PassKind::Transfer,
        [&](fg::PassBuilder& builder, Data& d) {
            d.source = builder.copy_source(source);
            d.target = builder.copy_destination(target);
        },
        [copy](const Data& d, fg::PassContext& context) { copy(context, d.source, context.buffer(d.target)); });
    graph.request_output(data.target);
}

}  // namespace

void add_readback_pass(fg::FrameGraph& graph, fg::ImageHandle image, VkBuffer host_buffer, VkDeviceSize bytes,
                       const std::string& name) {
    add_copy_to_host(graph, image, host_buffer, bytes, name,
                     [](fg::PassContext& context, fg::ImageHandle source, VkBuffer target) {
                         const VkExtent2D extent = context.extent(source);
                         VkBufferImageCopy region{};
                         region.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
                         region.imageExtent = {extent.width, extent.height, 1};
                         vkCmdCopyImageToBuffer(context.cmd(), context.image(source),
                                                VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, target, 1, &region);
                     });
}

void add_readback_pass(fg::FrameGraph& graph, fg::BufferHandle buffer, VkBuffer host_buffer, VkDeviceSize bytes,
                       const std::string& name) {
    add_copy_to_host(graph, buffer, host_buffer, bytes, name,
                     [bytes](fg::PassContext& context, fg::BufferHandle source, VkBuffer target) {
                         const VkBufferCopy region{0, 0, bytes};
                         vkCmdCopyBuffer(context.cmd(), context.buffer(source), target, 1, &region);
                     });
}

}  // namespace vkw::passes
