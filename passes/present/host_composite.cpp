// add_host_composite_pass (host_composite.hpp).
#include "passes/present/host_composite.hpp"

#include "engine/framegraph/pass_context.hpp"

#include <string>

namespace vkw::passes {

fg::ImageHandle add_host_composite_pass(fg::FrameGraph& graph, fg::ImageHandle hdr, fg::ImageHandle scene_depth,
                                        fg::ImageHandle host_color, fg::ImageHandle host_depth) {
    struct Data {
        fg::ImageHandle color;
    };
    // The host's formats are its choice: one pipeline per pair it has given.
    const std::string key = "host composite " + std::to_string(graph.resources()[host_color.index].image.format) + "/" +
                            std::to_string(graph.resources()[host_depth.index].image.format);
    const auto& data = graph.add_pass<Data>(
        kHostCompositePass, fg::PassKind::Graphics,
        [&](fg::PassBuilder& builder, Data& d) {
            // texelFetch reads: one texel per pixel (the depth at its own resolution), no filter applies.
            builder.sample("hdr", hdr, fg::Filter::Nearest);
            builder.sample("scene_depth", scene_depth, fg::Filter::Nearest);
            // Both of the host's targets keep what the host drew: the test decides per pixel.
            d.color = builder.color_attachment(host_color, fg::LoadOp::Load);
            (void)builder.depth_stencil_attachment(host_depth, fg::LoadOp::Load);
        },
        [key](const Data&, fg::PassContext& context) {
            GraphicsPipelineDesc desc;
            desc.vertex_shader = "common/fullscreen.vert";
            desc.fragment_shader = "present/host_composite.frag";
            desc.depth_test = true;
            desc.depth_write = true;
            desc.depth_compare = VK_COMPARE_OP_GREATER_OR_EQUAL;  // reverse Z: nearer is greater
            const Pipeline& pipeline = context.pipeline(key, desc);
            context.bind(pipeline);
            vkCmdDraw(context.cmd(), 3, 1, 0, 0);
        });
    return data.color;
}

}  // namespace vkw::passes
