#include "passes/receivers/receiver_draws.hpp"

namespace vkw::passes {

void use_receiver_mesh_vertices(GraphicsPipelineDesc& desc) {
    desc.vertex_shader = "receivers/mesh.vert";
    desc.vertex_bindings = {{0, 6 * sizeof(float), VK_VERTEX_INPUT_RATE_VERTEX}};
    desc.vertex_attributes = {{0, 0, VK_FORMAT_R32G32B32_SFLOAT, 0},
                              {1, 0, VK_FORMAT_R32G32B32_SFLOAT, 3 * sizeof(float)}};
}

GraphicsPipelineDesc receiver_mesh_pipeline(const LightingInputs& lighting, const std::string& variant_suffix) {
    GraphicsPipelineDesc desc;
    use_receiver_mesh_vertices(desc);
    desc.fragment_shader = lighting.shader("receivers/receiver.frag") + variant_suffix;
    lighting.add_layout(desc.layout.bindings);
    desc.layout.push_constant_bytes = sizeof(ReceiverPush);
    desc.depth_test = true;
    desc.depth_write = true;
    return desc;
}

void draw_receiver_meshes(const fg::PassContext& context, const Pipeline& pipeline, const ReceiverMeshes& meshes,
                          fg::BufferHandle vertices, fg::BufferHandle indices, const glm::vec4& view) {
    const VkBuffer vertex_buffer = context.buffer(vertices);
    const VkDeviceSize offset = 0;
    vkCmdBindVertexBuffers(context.cmd(), 0, 1, &vertex_buffer, &offset);
    vkCmdBindIndexBuffer(context.cmd(), context.buffer(indices), 0, VK_INDEX_TYPE_UINT32);
    for (const ReceiverDraw& draw : meshes.draws()) {
        context.push_constants(pipeline, ReceiverPush{glm::vec4(draw.albedo, 0.0f), view});
        vkCmdDrawIndexed(context.cmd(), draw.index_count, 1, draw.first_index, draw.vertex_offset, 0);
    }
}

}  // namespace vkw::passes
