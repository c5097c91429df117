// add_upscale_pass (upscale.hpp).
#include "passes/frame/upscale.hpp"

#include "engine/framegraph/pass_context.hpp"

#include <shader_structs/frame/upscale.frag.hpp>

#include <algorithm>
#include <cmath>

namespace vkw::passes {
namespace {

// The push-constant block of shaders/frame/upscale.frag, generated from its SPIR-V (tools/shader_structs).
using UpscalePush = glsl::upscale_frag::Push;

}  // namespace

uint32_t scaled_size(uint32_t output, double render_scale) {
    return std::max(1u, static_cast<uint32_t>(std::lround(double(output) * render_scale)));
}

fg::ImageHandle add_upscale_pass(fg::FrameGraph& graph, fg::ImageHandle source, uint32_t width, uint32_t height,
                                 const std::string& name) {
    struct Data {
        fg::ImageHandle target;
    };
    const auto& data = graph.add_pass<Data>(
        name, fg::PassKind::Graphics,
        [&](fg::PassBuilder& builder, Data& d) {
            builder.sample("source", source);  // bilinear, clamped
            const fg::ImageInfo info{VK_FORMAT_R32G32B32A32_SFLOAT, fg::SizeClass::Absolute, 1.0f, width, height};
            d.target = builder.create_image(name + " target", info);
            // Every pixel is written: what the image held before does not matter.
            d.target = builder.color_attachment(d.target, fg::LoadOp::DontCare);
        },
        [width, height](const Data&, fg::PassContext& context) {
            GraphicsPipelineDesc desc;
            desc.vertex_shader = "common/fullscreen.vert";
            desc.fragment_shader = "frame/upscale.frag";
            const Pipeline& pipeline = context.pipeline("upscale", desc);
            context.bind(pipeline);
            context.push_constants(pipeline, UpscalePush{1.0f / float(width), 1.0f / float(height)});
            vkCmdDraw(context.cmd(), 3, 1, 0, 0);
        });
    return data.target;
}

}  // namespace vkw::passes
