// add_caustic_receivers_pass (caustics_camera_receivers.hpp).
#include "passes/caustics/caustics_camera_receivers.hpp"

#include "engine/framegraph/pass_context.hpp"
#include "engine/vk/shader_variant.hpp"
#include "passes/common/frame_keys.hpp"
#include "passes/receivers/receiver_draws.hpp"

#include <cmath>

namespace vkw::passes {

namespace {
// SCENE_VIEW_GUARD of shaders/scene_views/scene_view.glsl (as passes/scene_views/scene_view.cpp has it).
constexpr double kGuardBand = 1.5;
}  // namespace

CameraCausticExtent camera_caustic_extent(uint32_t output_width, uint32_t output_height) {
    return {static_cast<uint32_t>(std::lround(kGuardBand * output_width)),
            static_cast<uint32_t>(std::lround(kGuardBand * output_height))};
}

fg::ImageHandle add_caustic_receivers_pass(fg::FrameGraph& graph, const ReceiverMeshes* meshes,
                                           CameraCausticExtent extent, float clip_margin) {
    struct Data {
        std::optional<fg::BufferHandle> vertices, indices;
        fg::ImageHandle target, depth;
    };
    const auto& data = graph.add_pass<Data>(
        "caustic receivers", fg::PassKind::Graphics,
        [&](fg::PassBuilder& builder, Data& d) {
            if (meshes && !meshes->empty()) {
                d.vertices = builder.vertex_buffer(meshes->import_vertices(graph));
                d.indices = builder.index_buffer(meshes->import_indices(graph));
            }
            builder.uniform_buffer("FrameConstants", graph.blackboard().get(keys::kFrameConstants),
                                   VK_PIPELINE_STAGE_2_VERTEX_SHADER_BIT | VK_PIPELINE_STAGE_2_FRAGMENT_SHADER_BIT);
            const fg::ImageInfo target{VK_FORMAT_R32G32B32A32_SFLOAT, fg::SizeClass::Absolute, 1.0f, extent.width,
                                       extent.height};
            d.target =
                builder.color_attachment(builder.create_image("caustic receivers view", target), fg::LoadOp::Clear);
            const fg::ImageInfo depth{VK_FORMAT_D32_SFLOAT, fg::SizeClass::Absolute, 1.0f, extent.width, extent.height};
            d.depth = builder.depth_stencil_attachment(builder.create_image("caustic receivers depth", depth),
                                                       fg::LoadOp::Clear, {.depth = 0.0f});
        },
        [meshes, clip_margin](const Data& d, fg::PassContext& context) {
            // y = -1: a scene view (the guard band); the fragment shader keeps what lies under the
            // mean level plus z, whichever side the camera is on.
            const glm::vec4 view(0.0f, -1.0f, clip_margin, 0.0f);
            GraphicsPipelineDesc desc;
            desc.vertex_shader = "receivers/floor.vert";
            desc.fragment_shader = ShaderVariant{"caustics/caustic_receivers.frag"}.file();
            desc.depth_test = true;
            desc.depth_write = true;
            const Pipeline& floor = context.pipeline("caustic receivers floor", desc);
            context.bind(floor);
            context.push_constants(floor, receiver_push(glm::vec4(0.0f), view));
            vkCmdDraw(context.cmd(), 6, 1, 0, 0);
            if (!d.vertices) return;
            GraphicsPipelineDesc mesh_desc = desc;
            use_receiver_mesh_vertices(mesh_desc);
            // Cutouts' holes show what lies behind them here too: that variant samples their alpha.
            const bool cutouts = meshes->has_cutouts();
            mesh_desc.fragment_shader =
                ShaderVariant{"caustics/caustic_receivers.frag"}.define("VKWATER_CUTOUT", cutouts).file();
            const Pipeline& mesh = context.pipeline(
                cutouts ? "caustic receivers meshes with cutouts" : "caustic receivers meshes", mesh_desc);
            draw_receiver_meshes(context, mesh, *meshes, *d.vertices, *d.indices, view);
        });
    return data.target;
}

}  // namespace vkw::passes
