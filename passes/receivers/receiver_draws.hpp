// What every pass that draws the receiver meshes shares: the push constants of the
// receiver shaders (mirroring shaders/receivers/receiver_push.glsl), the meshes' pipeline
// description and the draw loop. Used by the camera's receivers pass and the scene views.
#pragma once

#include "engine/framegraph/pass_context.hpp"
#include "engine/vk/pipeline.hpp"
#include "passes/receivers/lighting_inputs.hpp"
#include "passes/receivers/receiver_meshes.hpp"

#include <glm/glm.hpp>

namespace vkw::passes {

struct ReceiverPush {
    glm::vec4 albedo{0.0f};
    // x: 1 mirrored; y: side kept (+1 the camera's, -1 the other, 0 not a scene view); z: clip margin, m
    glm::vec4 view{0.0f};
};

// receivers/mesh.vert and its vertex layout (position, normal: 6 floats), for any fragment shader.
void use_receiver_mesh_vertices(GraphicsPipelineDesc& desc);

// receivers/mesh.vert + receivers/receiver.frag in the lighting inputs' variant (plus
// `variant_suffix`, e.g. the caustic layer's "_layer"), depth tested and written.
GraphicsPipelineDesc receiver_mesh_pipeline(const LightingInputs& lighting, const std::string& variant_suffix = "");

// Binds the meshes' buffers and draws each mesh with its albedo and `view`.
void draw_receiver_meshes(const fg::PassContext& context, const Pipeline& pipeline, const ReceiverMeshes& meshes,
                          fg::BufferHandle vertices, fg::BufferHandle indices, const glm::vec4& view);

}  // namespace vkw::passes
