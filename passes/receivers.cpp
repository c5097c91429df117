#include "passes/receivers.hpp"

#include "engine/framegraph/pass_context.hpp"
#include "engine/render/blackboard_keys.hpp"
#include "passes/lighting_inputs.hpp"

namespace vkw::passes {

void add_receivers_pass(fg::FrameGraph& graph, const ReceiverMeshes& meshes) {
    struct Data {
        fg::BufferHandle vertices, indices;
        fg::ImageHandle hdr, depth;
        LightingInputs lighting;
    };
    const auto& data = graph.add_pass<Data>(
        "receivers", fg::PassKind::Graphics,
        [&](fg::PassBuilder& builder, Data& d) {
            d.vertices = builder.vertex_buffer(meshes.import_vertices(graph));
            d.indices = builder.index_buffer(meshes.import_indices(graph));
            d.hdr = builder.color_attachment(graph.blackboard().get(keys::kHdrColor), fg::LoadOp::Load);
            d.depth = builder.depth_stencil_attachment(graph.blackboard().get(keys::kSceneDepth), fg::LoadOp::Load);
            d.lighting.declare(builder, graph.blackboard(), /*with_caustics=*/false);
        },
        [&meshes](const Data& d, fg::PassContext& context) {
            GraphicsPipelineDesc desc;
            desc.vertex_shader = "receivers/mesh.vert";
            desc.fragment_shader = d.lighting.shader("receivers/receiver.frag");
            d.lighting.add_layout(desc.layout.bindings);
            desc.layout.push_constant_bytes = sizeof(glm::vec4);
            desc.vertex_bindings = {{0, 6 * sizeof(float), VK_VERTEX_INPUT_RATE_VERTEX}};
            desc.vertex_attributes = {{0, 0, VK_FORMAT_R32G32B32_SFLOAT, 0},
                                      {1, 0, VK_FORMAT_R32G32B32_SFLOAT, 3 * sizeof(float)}};
            desc.depth_test = true;
            desc.depth_write = true;
            const Pipeline& pipeline = context.pipeline(desc.fragment_shader, desc);
            std::vector<fg::DescriptorBinding> bindings;
            d.lighting.add_bindings(context, bindings);
            context.bind(pipeline, bindings);
            const VkBuffer vertex_buffer = context.buffer(d.vertices);
            const VkDeviceSize offset = 0;
            vkCmdBindVertexBuffers(context.cmd(), 0, 1, &vertex_buffer, &offset);
            vkCmdBindIndexBuffer(context.cmd(), context.buffer(d.indices), 0, VK_INDEX_TYPE_UINT32);
            for (const ReceiverDraw& draw : meshes.draws()) {
                context.push_constants(pipeline, glm::vec4(draw.albedo, 0.0f));
                vkCmdDrawIndexed(context.cmd(), draw.index_count, 1, draw.first_index, draw.vertex_offset, 0);
            }
        });
    graph.blackboard().put(keys::kHdrColor, data.hdr);
    graph.blackboard().put(keys::kSceneDepth, data.depth);
}

}  // namespace vkw::passes
