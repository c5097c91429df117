// What every pass that draws the receiver meshes shares: the push constants of the
// receiver shaders (shaders/receivers/receiver_push.glsl), the meshes' pipeline
// description and the draw loop. Used by the camera's receivers pass and the scene views.
#pragma once

#include "engine/framegraph/pass_context.hpp"
#include "engine/vk/pipeline.hpp"
#include "passes/receivers/lighting_inputs.hpp"
#include "passes/receivers/receiver_meshes.hpp"

#include <glm/glm.hpp>
#include <shader_structs/receivers/receiver.frag.hpp>

namespace vkw::passes {

// The receiver shaders' push block (shaders/receivers/receiver_push.glsl), generated from its SPIR-V:
// albedo; view.x 1 mirrored, view.y the side kept (+1 the camera's, -1 the other, 0 not a scene view),
// view.z the clip margin in m; material.x the base colour factor's alpha, material.y the mesh
// variant's cutoff (negative: opaque).
using ReceiverPush = glsl::receiver_frag::Receiver;

// A receiver's push block; opaque unless `material` names a cutout.
inline ReceiverPush receiver_push(glm::vec4 albedo, glm::vec4 view,
                                  glm::vec4 material = glm::vec4(1.0f, -1.0f, 0.0f, 0.0f)) {
    return {albedo, view, material};
}

// receivers/mesh.vert and its vertex layout (position, normal, texture coordinates, RGBA colour: 12
// floats), for any fragment shader. A vertex shader that reads no normal (the sun shadow map's) takes
// the layout without that attribute: the validation layer reports an attribute no stage consumes.
void use_receiver_mesh_vertices(GraphicsPipelineDesc& desc, bool with_normal = true);

// receivers/mesh.vert + receivers/receiver.frag in the lighting inputs' variant (plus
// the caustic layer's macro when `caustic_layer`), depth tested and written. Where the meshes'
// base colour varies (ReceiverMeshes::varied_base_color), the mesh variant, which samples the base
// colour texture (`base_color_texture`) and multiplies in the vertex colour. `behind_first_layer`:
// a scene view's second layer, which samples the first (`first_layer`) and keeps what lies behind.
GraphicsPipelineDesc receiver_mesh_pipeline(const LightingInputs& lighting, const ReceiverMeshes& meshes,
                                            bool caustic_layer = false, bool behind_first_layer = false);

// Binds `pipeline` with the pass's declared resources (PassContext::bind) and the meshes' buffers,
// and draws each part with its albedo and `view`, and with its base colour texture where the
// pipeline samples one (a receiver_mesh_pipeline of meshes whose base colour varies, a cutout
// variant).
void draw_receiver_meshes(const fg::PassContext& context, const Pipeline& pipeline, const ReceiverMeshes& meshes,
                          fg::BufferHandle vertices, fg::BufferHandle indices, const glm::vec4& view);

}  // namespace vkw::passes
