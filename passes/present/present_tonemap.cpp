// add_present_tonemap_pass (present_tonemap.hpp).
#include "passes/present/present_tonemap.hpp"

#include "engine/framegraph/pass_context.hpp"

namespace vkw::passes {
namespace {

// Mirrors the push constants of shaders/present/present_tonemap.frag.
struct TonemapPush {
    float exposure;
    uint32_t encode_srgb;
};

}  // namespace

fg::ImageHandle add_present_tonemap_pass(fg::FrameGraph& graph, fg::ImageHandle hdr, fg::ImageHandle target,
                                         const PresentTonemapSettings* settings) {
    struct Data {
        fg::ImageHandle hdr;
        fg::ImageHandle target;
    };
    const auto& data = graph.add_pass<Data>(
        "present tonemap", fg::PassKind::Graphics,
        [&](fg::PassBuilder& builder, Data& d) {
            d.hdr = builder.sample(hdr);
            // Every pixel is written: what the image held before does not matter.
            d.target = builder.color_attachment(target, fg::LoadOp::DontCare);
        },
        [settings](const Data& d, fg::PassContext& context) {
            GraphicsPipelineDesc desc;
            desc.vertex_shader = "common/fullscreen.vert";
            desc.fragment_shader = "present/present_tonemap.frag";
            const Pipeline& pipeline = context.pipeline("present tonemap", desc);
            // texelFetch reads one texel per pixel: the sampler's filter never applies.
            context.bind(pipeline, {context.sampled_nearest(0, d.hdr)});
            context.push_constants(pipeline, TonemapPush{settings->exposure, settings->encode_srgb ? 1u : 0u});
            vkCmdDraw(context.cmd(), 3, 1, 0, 0);
        });
    return data.target;
}

}  // namespace vkw::passes
