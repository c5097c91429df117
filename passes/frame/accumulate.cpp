// add_sub_frame_accumulation (accumulate.hpp).
#include "passes/frame/accumulate.hpp"

#include "engine/framegraph/pass_context.hpp"

namespace vkw::passes {
namespace {

// Mirrors the push constants of shaders/frame/accumulate.comp.
struct AccumulatePush {
    uint32_t first;
    uint32_t last;
    float scale;
};

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
        fg::ImageHandle colour, sum;
    };
    const AccumulatePush push{index == 0 ? 1u : 0u, index + 1 == count ? 1u : 0u, 1.0f / static_cast<float>(count)};
    const auto& data = graph.add_pass<Data>(
        "sub-frame accumulation", fg::PassKind::Compute,
        [&](fg::PassBuilder& builder, Data& d) {
            const VkPipelineStageFlags2 stage = VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT;
            d.colour = builder.read_storage(colour, stage);
            d.sum = builder.read_write_storage(imported, stage);
        },
        [push](const Data& d, fg::PassContext& context) {
            ComputePipelineDesc desc;
            desc.shader = "frame/accumulate.comp";
            const Pipeline& pipeline = context.pipeline("sub-frame accumulation", desc);
            context.bind(pipeline, {context.storage_image(0, d.colour), context.storage_image(1, d.sum)});
            context.push_constants(pipeline, push);
            const VkExtent2D size = context.extent(d.sum);
            vkCmdDispatch(context.cmd(), (size.width + 7) / 8, (size.height + 7) / 8, 1);
        });
    return data.sum;
}

}  // namespace vkw::passes
