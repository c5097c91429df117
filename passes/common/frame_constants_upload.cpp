#include "passes/common/frame_constants_upload.hpp"

#include "engine/framegraph/pass_context.hpp"
#include "passes/common/frame_keys.hpp"

namespace vkw::passes {

void add_frame_constants_upload(fg::FrameGraph& graph, const FrameConstants* constants) {
    struct Data {
        fg::BufferHandle buffer;
    };
    // vkCmdUpdateBuffer takes at most 65536 bytes, far more than the block needs.
    static_assert(sizeof(FrameConstants) <= 65536);
    const auto& data = graph.add_pass<Data>(
        "upload frame constants", fg::PassKind::Transfer,
        [&](fg::PassBuilder& builder, Data& d) {
            d.buffer = builder.create_buffer("frame constants", {sizeof(FrameConstants)});
            d.buffer = builder.copy_destination(d.buffer);
        },
        [constants](const Data& d, fg::PassContext& context) {
            vkCmdUpdateBuffer(context.cmd(), context.buffer(d.buffer), 0, sizeof(FrameConstants), constants);
        });
    graph.blackboard().put(keys::kFrameConstants, data.buffer);
}

}  // namespace vkw::passes
