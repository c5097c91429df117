#include "passes/scene_views/scene_view.hpp"

#include "engine/framegraph/pass_context.hpp"
#include "engine/scene/effects.hpp"

#include "passes/caustics/caustic_layer.hpp"
#include "passes/receivers/receiver_draws.hpp"

#include <string>

namespace vkw::passes {

namespace {
// SCENE_VIEW_GUARD in shaders/scene_views/scene_view.glsl: the view's tangent of the half
// field of view over the camera's; the target grows by the same factor, keeping the
// camera's pixel density.
constexpr float kGuardBand = 1.5f;
}  // namespace

fg::ImageHandle add_scene_view_pass(fg::FrameGraph& graph, const ReceiverMeshes& meshes, const SceneViewSpec& spec) {
    struct Data {
        fg::BufferHandle vertices, indices;
        fg::ImageHandle target, depth;
        std::optional<fg::ImageHandle> first_layer;
        LightingInputs lighting;
        CausticLayerTarget layer;
    };
    const auto& data = graph.add_pass<Data>(
        spec.name, fg::PassKind::Graphics,
        [&](fg::PassBuilder& builder, Data& d) {
            // Reflected rays stay on the camera's side; refracted rays cross the surface.
            builder.serves(spec.behind        ? Effect::RefractionSecondLayer
                           : spec.camera_side ? Effect::Reflection
                                              : Effect::Refraction);
            if (spec.behind) {
                d.first_layer = builder.sample("first_layer", *spec.behind, fg::Filter::Nearest,
                                               VK_PIPELINE_STAGE_2_FRAGMENT_SHADER_BIT);
            }
            d.vertices = builder.vertex_buffer(meshes.import_vertices(graph));
            d.indices = builder.index_buffer(meshes.import_indices(graph));
            const fg::ImageInfo target{VK_FORMAT_R32G32B32A32_SFLOAT, fg::SizeClass::OutputRelative, kGuardBand};
            d.target = builder.color_attachment(builder.create_image(std::string(spec.name) + " target", target),
                                                fg::LoadOp::Clear);
            if (spec.caustic_layer && !spec.camera_side)
                d.layer.create(builder, std::string(spec.name) + " caustic", target);
            const fg::ImageInfo depth{VK_FORMAT_D32_SFLOAT, fg::SizeClass::OutputRelative, kGuardBand};
            d.depth = builder.depth_stencil_attachment(builder.create_image(std::string(spec.name) + " depth", depth),
                                                       fg::LoadOp::Clear, {.depth = 0.0f});
            d.lighting.declare(builder, graph.blackboard(), /*with_camera_medium=*/false);
        },
        [&meshes, spec](const Data& d, fg::PassContext& context) {
            const GraphicsPipelineDesc desc =
                receiver_mesh_pipeline(d.lighting, meshes, d.layer.written(), d.first_layer.has_value());
            const Pipeline& pipeline = context.pipeline(desc.fragment_shader, desc);
            const glm::vec4 view(spec.mirrored ? 1.0f : 0.0f, spec.camera_side ? 1.0f : -1.0f, spec.clip_margin, 0.0f);
            draw_receiver_meshes(context, pipeline, meshes, d.vertices, d.indices, view);
        });
    if (data.layer.image) {
        graph.blackboard().put(spec.behind ? keys::kRefractionViewBehindCaustic : keys::kRefractionViewCaustic,
                               *data.layer.image);
    }
    return data.target;
}

}  // namespace vkw::passes
