#include "passes/receivers/floor.hpp"

#include "engine/framegraph/pass_context.hpp"
#include "passes/caustics/caustic_layer.hpp"
#include "passes/common/frame_keys.hpp"
#include "passes/common/scene_depth.hpp"
#include "passes/receivers/lighting_inputs.hpp"
#include "passes/receivers/receiver_draws.hpp"

namespace vkw::passes {

void add_floor_pass(fg::FrameGraph& graph, bool caustic_layer) {
    struct Data {
        fg::ImageHandle hdr;
        fg::ImageHandle depth;
        LightingInputs lighting;
        CausticLayerTarget layer;
    };
    const auto& data = graph.add_pass<Data>(
        "floor", fg::PassKind::Graphics,
        [&](fg::PassBuilder& builder, Data& d) {
            d.hdr = hdr_colour_attachment(builder, graph.blackboard());
            d.layer.create_or_load(builder, graph.blackboard(), caustic_layer);
            d.depth = scene_depth_attachment(builder, graph.blackboard());
            d.lighting.declare(builder, graph.blackboard());
        },
        [](const Data& d, fg::PassContext& context) {
            GraphicsPipelineDesc desc;
            desc.vertex_shader = "receivers/floor.vert";
            desc.fragment_shader =
                d.lighting.shader("receivers/receiver.frag").define("VKWATER_CAUSTIC_LAYER", d.layer.written()).file();
            desc.depth_test = true;
            desc.depth_write = true;
            const Pipeline& pipeline = context.pipeline(desc.fragment_shader, desc);
            context.bind(pipeline);
            context.push_constants(pipeline, receiver_push(glm::vec4(0.0f), glm::vec4(0.0f)));  // the camera's own view
            vkCmdDraw(context.cmd(), 6, 1, 0, 0);
        });
    graph.blackboard().put(keys::kHdrColor, data.hdr);
    graph.blackboard().put(keys::kSceneDepth, data.depth);
    data.layer.publish(graph.blackboard());
}

}  // namespace vkw::passes
