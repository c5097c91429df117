#include "passes/sky.hpp"

#include "engine/framegraph/pass_context.hpp"
#include "engine/render/blackboard_keys.hpp"

namespace vkw::passes {

void add_sky_pass(fg::FrameGraph& graph) {
    struct Data {
        fg::BufferHandle constants;
        fg::ImageHandle hdr;
    };
    const auto& data = graph.add_pass<Data>(
        "sky", fg::PassKind::Graphics,
        [&](fg::PassBuilder& builder, Data& d) {
            d.constants = builder.uniform_buffer(graph.blackboard().get(keys::kFrameConstants));
            // HDR radiance in 32-bit float: the sun's disk alone exceeds half-float range
            // once E_s > 4.4 W m^-2 (PHYSICS.md section 1).
            d.hdr = builder.create_image("hdr colour", {VK_FORMAT_R32G32B32A32_SFLOAT});
            d.hdr = builder.color_attachment(d.hdr, fg::LoadOp::DontCare);
        },
        [](const Data& d, fg::PassContext& context) {
            GraphicsPipelineDesc desc;
            desc.vertex_shader = "common/fullscreen.vert";
            desc.fragment_shader = "sky/sky.frag";
            desc.layout.bindings = {{0, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, 1, VK_SHADER_STAGE_FRAGMENT_BIT}};
            const Pipeline& pipeline = context.pipeline("sky", desc);
            context.bind(pipeline, {context.uniform_buffer(0, d.constants)});
            vkCmdDraw(context.cmd(), 3, 1, 0, 0);
        });
    graph.blackboard().put(keys::kHdrColor, data.hdr);
}

}  // namespace vkw::passes
