#include "passes/common/zeroed_buffer.hpp"

#include "engine/core/errors.hpp"
#include "engine/framegraph/pass_context.hpp"

#include <string>

namespace vkw::passes {

fg::BufferHandle add_zeroed_buffer_pass(fg::FrameGraph& graph, const std::string& pass_name,
                                        const std::string& buffer_name, VkDeviceSize bytes,
                                        std::optional<fg::EffectTag> effect, VkDeviceSize zeroed_bytes) {
    if (zeroed_bytes != VK_WHOLE_SIZE && (zeroed_bytes == 0 || zeroed_bytes > bytes || zeroed_bytes % 4 != 0)) {
        throw InternalError(pass_name + ": " + std::to_string(zeroed_bytes) + " bytes to zero of " +
                            std::to_string(bytes) + " (accepted: a positive multiple of 4, at most all)");
    }
    struct Data {
        fg::BufferHandle buffer;
    };
    const auto& data = graph.add_pass<Data>(
        pass_name, fg::PassKind::Transfer,
        [&](fg::PassBuilder& builder, Data& d) {
            if (effect) builder.serves(*effect);
            d.buffer = builder.copy_destination(builder.create_buffer(buffer_name, {bytes}));
        },
        [zeroed_bytes](const Data& d, fg::PassContext& context) {
            vkCmdFillBuffer(context.cmd(), context.buffer(d.buffer), 0, zeroed_bytes, 0);
        });
    return data.buffer;
}

}  // namespace vkw::passes
