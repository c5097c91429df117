// add_upscale_pass (upscale.hpp).
#include "passes/frame/upscale.hpp"

#include "engine/framegraph/pass_context.hpp"

#include <algorithm>
#include <cmath>

namespace vkw::passes {
namespace {

// Mirrors the push constants of shaders/frame/upscale.frag.
struct UpscalePush {
    float inverse_width;
    float inverse_height;
};

}  // namespace

uint32_t scaled_size(uint32_t output, double render_scale) {
    return std::max(1u, static_cast<uint32_t>(std::lround(double(output) * render_scale)));
}

fg::ImageHandle add_upscale_pass(fg::FrameGraph& graph, fg::ImageHandle source, uint32_t width, uint32_t height,
                                 const std::string& name) {
    struct Data {
        fg::ImageHandle source;
        fg::ImageHandle target;
    };
    const auto& data = graph.add_pass<Data>(
        name, fg::PassKind::Graphics,
        [&](fg::PassBuilder& builder, Data& d) {
            d.source = builder.sample(source);
            const fg::ImageInfo info{VK_FORMAT_R32G32B32A32_SFLOAT, fg::SizeClass::Absolute, 1.0f, width, height};
            d.target = builder.create_image(name + " target", info);
            // Every pixel is written: what the image held before does not matter.
            d.target = builder.color_attachment(d.target, fg::LoadOp::DontCare);
        },
        [width, height](const Data& d, fg::PassContext& context) {
            GraphicsPipelineDesc desc;
            desc.vertex_shader = "common/fullscreen.vert";
            desc.fragment_shader = "frame/upscale.frag";
            const Pipeline& pipeline = context.pipeline("upscale", desc);
            context.bind(pipeline, {context.sampled(0, d.source)});  // the bilinear, clamped sampler
            context.push_constants(pipeline, UpscalePush{1.0f / float(width), 1.0f / float(height)});
            vkCmdDraw(context.cmd(), 3, 1, 0, 0);
        });
    return data.target;
}

}  // namespace vkw::passes
