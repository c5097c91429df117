// add_godray_composite_pass (godrays_composite.hpp).
#include "passes/godrays/godrays_composite.hpp"

#include "engine/framegraph/pass_context.hpp"
#include "engine/scene/effects.hpp"
#include "passes/common/frame_keys.hpp"

#include <optional>

namespace vkw::passes {

void add_godray_composite_pass(fg::FrameGraph& graph, fg::ImageHandle radiance, fg::ImageHandle view_depth,
                               bool inscatter_layer) {
    struct Data {
        fg::BufferHandle constants;
        fg::ImageHandle radiance, view_depth, scene_depth, hdr;
        std::optional<fg::ImageHandle> layer;
    };
    const auto& data = graph.add_pass<Data>(
        "godray composite", fg::PassKind::Graphics,
        [&](fg::PassBuilder& builder, Data& d) {
            builder.serves(Effect::VolumeCaustics);
            const VkPipelineStageFlags2 stage = VK_PIPELINE_STAGE_2_FRAGMENT_SHADER_BIT;
            d.constants = builder.uniform_buffer(graph.blackboard().get(keys::kFrameConstants), stage);
            d.radiance = builder.sample(radiance, stage);
            d.view_depth = builder.sample(view_depth, stage);
            d.scene_depth = builder.sample(graph.blackboard().get(keys::kSceneDepth), stage);
            d.hdr = builder.color_attachment(graph.blackboard().get(keys::kHdrColor), fg::LoadOp::Load);
            if (inscatter_layer) {
                // Cleared to 0 and blended like the HDR colour: it ends holding the godrays alone.
                d.layer = builder.color_attachment(
                    builder.create_image("in-scatter layer", {VK_FORMAT_R32G32B32A32_SFLOAT}), fg::LoadOp::Clear);
            }
        },
        [](const Data& d, fg::PassContext& context) {
            GraphicsPipelineDesc desc;
            desc.vertex_shader = "common/fullscreen.vert";
            desc.fragment_shader =
                d.layer ? "godrays/godray_composite.frag.layer" : "godrays/godray_composite.frag.plain";
            desc.additive_blend = true;
            const Pipeline& pipeline = context.pipeline(desc.fragment_shader, desc);
            context.bind(pipeline,
                         {context.uniform_buffer(0, d.constants), context.sampled_nearest(1, d.radiance),
                          context.sampled_nearest(2, d.view_depth), context.sampled_nearest(3, d.scene_depth)});
            vkCmdDraw(context.cmd(), 3, 1, 0, 0);
        });
    graph.blackboard().put(keys::kHdrColor, data.hdr);
    if (data.layer) graph.blackboard().put(keys::kInScatterLayer, *data.layer);
}

}  // namespace vkw::passes
