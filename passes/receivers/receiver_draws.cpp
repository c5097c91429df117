#include "passes/receivers/receiver_draws.hpp"

namespace vkw::passes {

void use_receiver_mesh_vertices(GraphicsPipelineDesc& desc, bool with_normal) {
    desc.vertex_shader = "receivers/mesh.vert";
    desc.vertex_bindings = {{0, kReceiverVertexBytes, VK_VERTEX_INPUT_RATE_VERTEX}};
    desc.vertex_attributes = {{0, 0, VK_FORMAT_R32G32B32_SFLOAT, 0},
                              {1, 0, VK_FORMAT_R32G32B32_SFLOAT, 3 * sizeof(float)},
                              {2, 0, VK_FORMAT_R32G32_SFLOAT, 6 * sizeof(float)},
                              {3, 0, VK_FORMAT_R32G32B32A32_SFLOAT, 8 * sizeof(float)}};
    if (!with_normal) desc.vertex_attributes.erase(desc.vertex_attributes.begin() + 1);  // location 1
}

GraphicsPipelineDesc receiver_mesh_pipeline(const LightingInputs& lighting, const ReceiverMeshes& meshes,
                                            bool caustic_layer, bool behind_first_layer) {
    GraphicsPipelineDesc desc;
    use_receiver_mesh_vertices(desc);
    const bool varied = meshes.varied_base_color();
    desc.fragment_shader = lighting.shader("receivers/receiver.frag")
                               .define("VKWATER_MESH_BASE_COLOR", varied)
                               .define("VKWATER_CAUSTIC_LAYER", caustic_layer)
                               .define("VKWATER_SCENE_VIEW_BEHIND", behind_first_layer)
                               .file();
    desc.depth_test = true;
    desc.depth_write = true;
    return desc;
}

void draw_receiver_meshes(const fg::PassContext& context, const Pipeline& pipeline, const ReceiverMeshes& meshes,
                          fg::BufferHandle vertices, fg::BufferHandle indices, const glm::vec4& view) {
    // Meshes whose base colour varies have textures (ReceiverMeshes): the white texel stands in
    // until each draw pushes its own.
    const bool textured = meshes.varied_base_color();
    context.bind(pipeline,
                 textured ? std::vector{meshes.textures().binding(-1)} : std::vector<fg::DescriptorBinding>{});
    const VkBuffer vertex_buffer = context.buffer(vertices);
    const VkDeviceSize offset = 0;
    vkCmdBindVertexBuffers(context.cmd(), 0, 1, &vertex_buffer, &offset);
    vkCmdBindIndexBuffer(context.cmd(), context.buffer(indices), 0, VK_INDEX_TYPE_UINT32);
    for (const ReceiverDraw& draw : meshes.draws()) {
        // Push descriptors update incrementally: the pass's other bindings stay as they were
        // pushed. A pipeline that samples no texture skips it.
        if (textured) context.push_descriptors(pipeline, {meshes.textures().binding(draw.texture)});
        context.push_constants(pipeline, receiver_push(glm::vec4(draw.albedo, 0.0f), view,
                                                       glm::vec4(draw.alpha, draw.alpha_cutoff, 0.0f, 0.0f)));
        vkCmdDrawIndexed(context.cmd(), draw.index_count, 1, draw.first_index, draw.vertex_offset, 0);
    }
}

}  // namespace vkw::passes
