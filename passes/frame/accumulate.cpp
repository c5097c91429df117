// add_sub_frame_accumulation (accumulate.hpp).
#include "passes/frame/accumulate.hpp"

#include "engine/framegraph/pass_context.hpp"

#include <shader_structs/frame/accumulate.comp.hpp>

namespace vkw::passes {
namespace {

// The push-constant block of shaders/frame/accumulate.comp, generated from its SPIR-V (tools/shader_structs).
using AccumulatePush = glsl::accumulate_comp::Push;

// Between sub-frames the sum waits where the accumulation reads and writes it.
fg::AccessState sum_state() { return fg::access_state(fg::Use::StorageImageReadWrite, fg::PassKind::Compute); }

}  // namespace

fg::ImageHandle add_sub_frame_accumulation(fg::FrameGraph& graph, fg::ImageHandle colour, fg::ImportedImage sum,
                                           uint32_t index, uint32_t count) {
    // The first sub-frame overwrites the sum: what it held before does not matter.
    sum.initial = index == 0 ? fg::AccessState{} : sum_state();
    sum.final_state = sum_state();
    const fg::ImageHandle imported = graph.import_image("sub-frame sum", sum);
    struct Data {
        fg::ImageHandle sum;
    };
    const AccumulatePush push{index == 0 ? 1u : 0u, index + 1 == count ? 1u : 0u, 1.0f / static_cast<float>(count)};
    const auto& data = graph.add_pass<Data>(
        "sub-frame accumulation", fg::PassKind::Compute,
        [&](fg::PassBuilder& builder, Data& d) {
            builder.read_storage("sub_frame", colour);
            d.sum = builder.read_write_storage("sum", imported);
        },
        [push](const Data& d, fg::PassContext& context) {
            const Pipeline& pipeline =
                context.pipeline("sub-frame accumulation", ComputePipelineDesc{"frame/accumulate.comp"});
            context.bind(pipeline);
            context.push_constants(pipeline, push);
            const VkExtent2D size = context.extent(d.sum);
            vkCmdDispatch(context.cmd(), (size.width + 7) / 8, (size.height + 7) / 8, 1);
        });
    return data.sum;
}

}  // namespace vkw::passes
