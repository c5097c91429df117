#include "passes/sky/sky.hpp"

#include "engine/framegraph/pass_context.hpp"
#include "engine/vk/shader_variant.hpp"
#include "passes/common/frame_keys.hpp"
#include "passes/water/camera_medium.hpp"
#include "passes/water/scene_optics.hpp"

namespace vkw::passes {

void add_sky_pass(fg::FrameGraph& graph, bool infinite_water) {
    struct Data {
        fg::ImageHandle hdr;
        bool per_pixel_medium = false;  // the camera-medium split runs
        bool infinite_water = false;
    };
    const auto& data = graph.add_pass<Data>(
        "sky", fg::PassKind::Graphics,
        [&](fg::PassBuilder& builder, Data& d) {
            builder.uniform_buffer("FrameConstants", graph.blackboard().get(keys::kFrameConstants));
            // HDR radiance in 32-bit float: the sun's disk alone exceeds half-float range
            // once E_s > 4.4 W m^-2 (docs/model.md section 1).
            d.hdr = builder.create_image("hdr colour", {VK_FORMAT_R32G32B32A32_SFLOAT});
            d.hdr = builder.color_attachment(d.hdr, fg::LoadOp::DontCare);
            d.per_pixel_medium = graph.blackboard().has(keys::kCameraMedium);
            if (d.per_pixel_medium) builder.sample("camera_medium_mask", graph.blackboard().get(keys::kCameraMedium));
            d.infinite_water = infinite_water;
            if (infinite_water) builder.read_storage("Optics", graph.blackboard().get(keys::kSceneOptics));
        },
        [](const Data& d, fg::PassContext& context) {
            GraphicsPipelineDesc desc;
            desc.vertex_shader = "common/fullscreen.vert";
            desc.fragment_shader = ShaderVariant{"sky/sky.frag"}
                                       .define("VKWATER_PER_PIXEL_MEDIUM", d.per_pixel_medium)
                                       .define("VKWATER_INFINITE_WATER", d.infinite_water)
                                       .file();
            const Pipeline& pipeline = context.pipeline(desc.fragment_shader, desc);
            context.bind(pipeline);
            vkCmdDraw(context.cmd(), 3, 1, 0, 0);
        });
    graph.blackboard().put(keys::kHdrColor, data.hdr);
}

}  // namespace vkw::passes
