// add_godray_composite_pass (godrays_composite.hpp).
#include "passes/godrays/godrays_composite.hpp"

#include "engine/framegraph/pass_context.hpp"
#include "engine/scene/effects.hpp"
#include "engine/vk/shader_variant.hpp"
#include "passes/common/frame_keys.hpp"

#include <optional>

namespace vkw::passes {

void add_godray_composite_pass(fg::FrameGraph& graph, fg::ImageHandle radiance, fg::ImageHandle view_depth,
                               bool inscatter_layer) {
    struct Data {
        fg::ImageHandle hdr;
        std::optional<fg::ImageHandle> layer;
    };
    const auto& data = graph.add_pass<Data>(
        "godray composite", fg::PassKind::Graphics,
        [&](fg::PassBuilder& builder, Data& d) {
            builder.serves(Effect::VolumeCaustics);
            builder.uniform_buffer("FrameConstants", graph.blackboard().get(keys::kFrameConstants));
            builder.sample("godrays", radiance, fg::Filter::Nearest);
            builder.sample("view_depth", view_depth, fg::Filter::Nearest);
            builder.sample("scene_depth", graph.blackboard().get(keys::kSceneDepth), fg::Filter::Nearest);
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
            desc.fragment_shader = ShaderVariant{"godrays/godray_composite.frag"}
                                       .define("VKWATER_INSCATTER_LAYER", d.layer.has_value())
                                       .file();
            desc.additive_blend = true;
            const Pipeline& pipeline = context.pipeline(desc.fragment_shader, desc);
            context.bind(pipeline);
            vkCmdDraw(context.cmd(), 3, 1, 0, 0);
        });
    graph.blackboard().put(keys::kHdrColor, data.hdr);
    if (data.layer) graph.blackboard().put(keys::kInScatterLayer, *data.layer);
}

}  // namespace vkw::passes
