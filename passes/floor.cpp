#include "passes/floor.hpp"

#include "engine/framegraph/pass_context.hpp"
#include "engine/render/blackboard_keys.hpp"
#include "passes/lighting_inputs.hpp"

namespace vkw::passes {

void add_floor_pass(fg::FrameGraph& graph) {
    struct Data {
        fg::BufferHandle constants;
        fg::BufferHandle optics;
        fg::ImageHandle hdr;
        fg::ImageHandle depth;
        LightingInputs lighting;
    };
    const auto& data = graph.add_pass<Data>(
        "floor", fg::PassKind::Graphics,
        [&](fg::PassBuilder& builder, Data& d) {
            d.constants = builder.uniform_buffer(graph.blackboard().get(keys::kFrameConstants),
                                                 VK_PIPELINE_STAGE_2_VERTEX_SHADER_BIT |
                                                     VK_PIPELINE_STAGE_2_FRAGMENT_SHADER_BIT);
            d.optics = builder.read_storage(graph.blackboard().get(keys::kSceneOptics));
            d.hdr = builder.color_attachment(graph.blackboard().get(keys::kHdrColor), fg::LoadOp::Load);
            d.depth = builder.create_image("scene depth", {VK_FORMAT_D32_SFLOAT});
            d.depth = builder.depth_stencil_attachment(d.depth, fg::LoadOp::Clear, {.depth = 0.0f});
            d.lighting.declare(builder, graph.blackboard());
        },
        [](const Data& d, fg::PassContext& context) {
            GraphicsPipelineDesc desc;
            desc.vertex_shader = "receivers/floor.vert";
            desc.fragment_shader = d.lighting.shader("receivers/receiver.frag");
            desc.layout.bindings = {
                {0, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, 1, VK_SHADER_STAGE_VERTEX_BIT | VK_SHADER_STAGE_FRAGMENT_BIT},
                {1, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, 1, VK_SHADER_STAGE_FRAGMENT_BIT}};
            d.lighting.add_layout(desc.layout.bindings);
            desc.depth_test = true;
            desc.depth_write = true;
            const Pipeline& pipeline = context.pipeline(desc.fragment_shader, desc);
            std::vector<fg::DescriptorBinding> bindings{context.uniform_buffer(0, d.constants),
                                                        context.storage_buffer(1, d.optics)};
            d.lighting.add_bindings(context, bindings);
            context.bind(pipeline, bindings);
            vkCmdDraw(context.cmd(), 6, 1, 0, 0);
        });
    graph.blackboard().put(keys::kHdrColor, data.hdr);
    graph.blackboard().put(keys::kSceneDepth, data.depth);
}

}  // namespace vkw::passes
