// Copies a graph buffer into a host-visible buffer owned by the test (imported into the graph,
// handed back in the host-read state) and requests it as the graph's output: the buffer
// counterpart of passes/readback.hpp.
#pragma once

#include "engine/framegraph/frame_graph.hpp"
#include "engine/framegraph/pass_context.hpp"

namespace vkw::test {

inline void add_buffer_readback(fg::FrameGraph& graph, fg::BufferHandle source, VkBuffer host_buffer,
                                VkDeviceSize bytes) {
    fg::ImportedBuffer imported{host_buffer, bytes};
    imported.final_state = fg::access_state(fg::Use::HostRead, fg::PassKind::Transfer);
    const fg::BufferHandle target = graph.import_buffer("buffer readback", imported);
    struct Data {
        fg::BufferHandle source;
        fg::BufferHandle target;
    };
    const auto& data = graph.add_pass<Data>(
        "buffer readback", fg::PassKind::Transfer,
        [&](fg::PassBuilder& builder, Data& d) {
            d.source = builder.copy_source(source);
            d.target = builder.copy_destination(target);
        },
        [bytes](const Data& d, fg::PassContext& context) {
            const VkBufferCopy region{0, 0, bytes};
            vkCmdCopyBuffer(context.cmd(), context.buffer(d.source), context.buffer(d.target), 1, &region);
        });
    graph.request_output(data.target);
}

}  // namespace vkw::test
