// The per-pixel camera medium (camera_medium.hpp).
#include "passes/water/camera_medium.hpp"

#include "engine/framegraph/pass_context.hpp"
#include "engine/scene/effects.hpp"
#include "passes/common/frame_keys.hpp"
#include "passes/water/water_surface_draw.hpp"

namespace vkw::passes {

void add_camera_medium_pass(fg::FrameGraph& graph, const WaterSurfaceBuffers& surface, double bottom_y,
                            double amplitude) {
    WaterSurfacePush push = water_surface_push(surface, 0);
    push.bottom_y = static_cast<float>(bottom_y);
    push.amplitude = static_cast<float>(amplitude);
    struct Data {
        WaterSurfaceReads surface;
        fg::ImageHandle mask;
    };
    const auto& data = graph.add_pass<Data>(
        "camera medium", fg::PassKind::Graphics,
        [&](fg::PassBuilder& builder, Data& d) {
            builder.serves(Effect::UnderwaterView);
            builder.uniform_buffer("FrameConstants", graph.blackboard().get(keys::kFrameConstants));
            d.surface.declare(builder, surface);
            d.mask = builder.create_image("camera medium", {VK_FORMAT_R8_UNORM});
            d.mask = builder.color_attachment(d.mask, fg::LoadOp::DontCare);
        },
        [push](const Data& d, fg::PassContext& context) {
            GraphicsPipelineDesc desc;
            desc.vertex_shader = "common/fullscreen.vert";
            desc.fragment_shader = "water/camera_medium_mask.frag";
            const std::string key = d.surface.specialise(desc, "camera medium");
            const Pipeline& pipeline = context.pipeline(key, desc);
            context.bind(pipeline, d.surface.stand_ins(context));
            context.push_constants(pipeline, push);
            vkCmdDraw(context.cmd(), 3, 1, 0, 0);
        });
    graph.blackboard().put(keys::kCameraMedium, data.mask);
}

}  // namespace vkw::passes
