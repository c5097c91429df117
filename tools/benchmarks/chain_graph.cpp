#include "tools/benchmarks/chain_graph.hpp"

#include "engine/framegraph/pass_context.hpp"

namespace vkw::chain {

fg::ImageHandle add_chain(fg::FrameGraph& graph) {
    struct GradientData {
        fg::ImageHandle pattern;
    };
    const auto& gradient = graph.add_pass<GradientData>(
        "gradient", fg::PassKind::Compute,
        [](fg::PassBuilder& builder, GradientData& d) {
            d.pattern = builder.create_image("pattern", {VK_FORMAT_R32G32B32A32_SFLOAT});
            d.pattern = builder.write_storage("target", d.pattern);
        },
        [](const GradientData& d, fg::PassContext& context) {
            ComputePipelineDesc desc;
            desc.shader = kPatternShader;
            desc.layout.bindings = {{0, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE, 1, VK_SHADER_STAGE_COMPUTE_BIT}};
            const Pipeline& pipeline = context.pipeline("gradient", desc);
            context.bind(pipeline);
            context.dispatch(pipeline, d.pattern);
        });
    struct CopyData {
        fg::ImageHandle pattern;
        fg::ImageHandle doubled;
    };
    const auto& copy = graph.add_pass<CopyData>(
        "copy texels", fg::PassKind::Graphics,
        [&](fg::PassBuilder& builder, CopyData& d) {
            d.pattern = builder.sample("source", gradient.pattern);
            d.doubled = builder.create_image("doubled", {VK_FORMAT_R32G32B32A32_SFLOAT});
            d.doubled = builder.color_attachment(d.doubled, fg::LoadOp::DontCare);
        },
        [](const CopyData&, fg::PassContext& context) {
            GraphicsPipelineDesc desc;
            desc.vertex_shader = "common/fullscreen.vert";
            desc.fragment_shader = kCopyShader;
            desc.layout.bindings = {{0, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, 1, VK_SHADER_STAGE_FRAGMENT_BIT}};
            const Pipeline& pipeline = context.pipeline("copy", desc);
            context.bind(pipeline);
            vkCmdDraw(context.cmd(), 3, 1, 0, 0);
        });
    return copy.doubled;
}

}  // namespace vkw::chain
