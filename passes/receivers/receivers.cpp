#include "passes/receivers/receivers.hpp"

#include "engine/framegraph/pass_context.hpp"
#include "passes/caustics/caustic_layer.hpp"
#include "passes/common/frame_keys.hpp"
#include "passes/common/scene_depth.hpp"
#include "passes/receivers/receiver_draws.hpp"

namespace vkw::passes {

void add_receivers_pass(fg::FrameGraph& graph, const ReceiverMeshes& meshes) {
    struct Data {
        fg::BufferHandle vertices, indices;
        fg::ImageHandle hdr, depth;
        LightingInputs lighting;
        CausticLayerTarget layer;
    };
    const auto& data = graph.add_pass<Data>(
        "receivers", fg::PassKind::Graphics,
        [&](fg::PassBuilder& builder, Data& d) {
            d.vertices = builder.vertex_buffer(meshes.import_vertices(graph));
            d.indices = builder.index_buffer(meshes.import_indices(graph));
            d.hdr = hdr_colour_attachment(builder, graph.blackboard());
            d.layer.load(builder, graph.blackboard());
            d.depth = builder.depth_stencil_attachment(graph.blackboard().get(keys::kSceneDepth), fg::LoadOp::Load);
            d.lighting.declare(builder, graph.blackboard());
        },
        [&meshes](const Data& d, fg::PassContext& context) {
            const GraphicsPipelineDesc desc = receiver_mesh_pipeline(d.lighting, meshes, d.layer.written());
            const Pipeline& pipeline = context.pipeline(desc.fragment_shader, desc);
            draw_receiver_meshes(context, pipeline, meshes, d.vertices, d.indices,
                                 glm::vec4(0.0f));  // the camera's view
        });
    graph.blackboard().put(keys::kHdrColor, data.hdr);
    graph.blackboard().put(keys::kSceneDepth, data.depth);
    data.layer.publish(graph.blackboard());
}

}  // namespace vkw::passes
