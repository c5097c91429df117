#include "passes/water_shading.hpp"

#include "engine/framegraph/pass_context.hpp"
#include "engine/render/blackboard_keys.hpp"
#include "passes/lighting_inputs.hpp"

namespace vkw::passes {

void add_water_shading_pass(fg::FrameGraph& graph, fg::BufferHandle surface, uint32_t grid_resolution) {
    struct Data {
        fg::BufferHandle surface;
        fg::ImageHandle hdr, depth;
        LightingInputs lighting;
    };
    const auto& data = graph.add_pass<Data>(
        "water", fg::PassKind::Graphics,
        [&](fg::PassBuilder& builder, Data& d) {
            builder.serves(fg::Effect::Water);
            d.surface = builder.read_storage(surface, VK_PIPELINE_STAGE_2_VERTEX_SHADER_BIT);
            d.hdr = builder.color_attachment(graph.blackboard().get(keys::kHdrColor), fg::LoadOp::Load);
            d.depth = builder.depth_stencil_attachment(graph.blackboard().get(keys::kSceneDepth), fg::LoadOp::Load);
            d.lighting.declare(builder, graph.blackboard());
        },
        [grid_resolution](const Data& d, fg::PassContext& context) {
            GraphicsPipelineDesc desc;
            desc.vertex_shader = "water_shading/water_surface.vert";
            desc.fragment_shader = d.lighting.shader("water_shading/water_surface.frag");
            desc.layout.bindings = {{2, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, 1, VK_SHADER_STAGE_VERTEX_BIT}};
            desc.layout.push_constant_bytes = sizeof(uint32_t);
            d.lighting.add_layout(desc.layout.bindings);
            desc.depth_test = true;
            desc.depth_write = true;
            const Pipeline& pipeline = context.pipeline(desc.fragment_shader, desc);
            std::vector<fg::DescriptorBinding> bindings{context.storage_buffer(2, d.surface)};
            d.lighting.add_bindings(context, bindings);
            context.bind(pipeline, bindings);
            context.push_constants(pipeline, grid_resolution);
            vkCmdDraw(context.cmd(), 6 * grid_resolution * grid_resolution, 1, 0, 0);
        });
    graph.blackboard().put(keys::kHdrColor, data.hdr);
    graph.blackboard().put(keys::kSceneDepth, data.depth);
}

}  // namespace vkw::passes
