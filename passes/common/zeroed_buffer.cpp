#include "passes/common/zeroed_buffer.hpp"

#include "engine/framegraph/pass_context.hpp"

namespace vkw::passes {

fg::BufferHandle add_zeroed_buffer_pass(fg::FrameGraph& graph, const std::string& pass_name,
                                        const std::string& buffer_name, VkDeviceSize bytes,
                                        std::optional<fg::EffectTag> effect) {
    struct Data {
        fg::BufferHandle buffer;
    };
    const auto& data = graph.add_pass<Data>(
        pass_name, fg::PassKind::Transfer,
        [&](fg::PassBuilder& builder, Data& d) {
            if (effect) builder.serves(*effect);
            d.buffer = builder.copy_destination(builder.create_buffer(buffer_name, {bytes}));
        },
        [](const Data& d, fg::PassContext& context) {
            vkCmdFillBuffer(context.cmd(), context.buffer(d.buffer), 0, VK_WHOLE_SIZE, 0);
        });
    return data.buffer;
}

}  // namespace vkw::passes
