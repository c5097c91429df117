#include "passes/sky/sky.hpp"

#include "engine/framegraph/pass_context.hpp"
#include "passes/common/frame_keys.hpp"
#include "passes/water/camera_medium.hpp"

#include <optional>
#include <vector>

namespace vkw::passes {

void add_sky_pass(fg::FrameGraph& graph) {
    struct Data {
        fg::BufferHandle constants;
        fg::ImageHandle hdr;
        std::optional<fg::ImageHandle> camera_medium;  // the camera-medium split's, when it runs
    };
    const auto& data = graph.add_pass<Data>(
        "sky", fg::PassKind::Graphics,
        [&](fg::PassBuilder& builder, Data& d) {
            d.constants = builder.uniform_buffer(graph.blackboard().get(keys::kFrameConstants));
            // HDR radiance in 32-bit float: the sun's disk alone exceeds half-float range
            // once E_s > 4.4 W m^-2 (docs/model.md section 1).
            d.hdr = builder.create_image("hdr colour", {VK_FORMAT_R32G32B32A32_SFLOAT});
            d.hdr = builder.color_attachment(d.hdr, fg::LoadOp::DontCare);
            if (graph.blackboard().has(keys::kCameraMedium)) {
                d.camera_medium = builder.sample(graph.blackboard().get(keys::kCameraMedium),
                                                 VK_PIPELINE_STAGE_2_FRAGMENT_SHADER_BIT);
            }
        },
        [](const Data& d, fg::PassContext& context) {
            GraphicsPipelineDesc desc;
            desc.vertex_shader = "common/fullscreen.vert";
            desc.fragment_shader = d.camera_medium ? "sky/sky.frag.per_pixel" : "sky/sky.frag.frame";
            std::vector<fg::DescriptorBinding> bindings{context.uniform_buffer(0, d.constants)};
            if (d.camera_medium) bindings.push_back(context.sampled(3, *d.camera_medium));
            const Pipeline& pipeline = context.pipeline(desc.fragment_shader, desc);
            context.bind(pipeline, bindings);
            vkCmdDraw(context.cmd(), 3, 1, 0, 0);
        });
    graph.blackboard().put(keys::kHdrColor, data.hdr);
}

}  // namespace vkw::passes
