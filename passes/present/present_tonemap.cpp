// add_present_tonemap_pass (present_tonemap.hpp).
#include "passes/present/present_tonemap.hpp"

#include "engine/framegraph/pass_context.hpp"

#include <shader_structs/present/present_tonemap.frag.hpp>

namespace vkw::passes {
namespace {

// The push-constant block of shaders/present/present_tonemap.frag, generated from its SPIR-V (tools/shader_structs).
using TonemapPush = glsl::present_tonemap_frag::Push;

}  // namespace

fg::ImageHandle add_present_tonemap_pass(fg::FrameGraph& graph, fg::ImageHandle hdr, fg::ImageHandle target,
                                         const PresentTonemapSettings* settings) {
    struct Data {
        fg::ImageHandle target;
    };
    const auto& data = graph.add_pass<Data>(
        "present tonemap", fg::PassKind::Graphics,
        [&](fg::PassBuilder& builder, Data& d) {
            // texelFetch reads one texel per pixel: the sampler's filter never applies.
            builder.sample("hdr", hdr, fg::Filter::Nearest);
            // Every pixel is written: what the image held before does not matter.
            d.target = builder.color_attachment(target, fg::LoadOp::DontCare);
        },
        [settings](const Data&, fg::PassContext& context) {
            GraphicsPipelineDesc desc;
            desc.vertex_shader = "common/fullscreen.vert";
            desc.fragment_shader = "present/present_tonemap.frag";
            const Pipeline& pipeline = context.pipeline("present tonemap", desc);
            context.bind(pipeline);
            context.push_constants(pipeline, TonemapPush{settings->exposure, settings->encode_srgb ? 1u : 0u});
            vkCmdDraw(context.cmd(), 3, 1, 0, 0);
        });
    return data.target;
}

}  // namespace vkw::passes
