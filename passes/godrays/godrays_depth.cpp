// add_godray_depth_pass (godrays_depth.hpp).
#include "passes/godrays/godrays_depth.hpp"

#include "engine/framegraph/pass_context.hpp"
#include "engine/scene/effects.hpp"
#include "engine/vk/shader_variant.hpp"
#include "passes/common/frame_keys.hpp"
#include "passes/water/camera_medium.hpp"

namespace vkw::passes {

fg::ImageHandle add_godray_depth_pass(fg::FrameGraph& graph, float scale) {
    struct Data {
        fg::ImageHandle view_depth;
        bool per_pixel_medium = false;
    };
    const auto& data = graph.add_pass<Data>(
        "godray depth", fg::PassKind::Compute,
        [&](fg::PassBuilder& builder, Data& d) {
            builder.serves(Effect::VolumeCaustics);
            builder.uniform_buffer("FrameConstants", graph.blackboard().get(keys::kFrameConstants));
            builder.sample("scene_depth", graph.blackboard().get(keys::kSceneDepth), fg::Filter::Nearest);
            d.per_pixel_medium = graph.blackboard().has(keys::kCameraMedium);
            if (d.per_pixel_medium) {
                builder.sample("camera_medium_mask", graph.blackboard().get(keys::kCameraMedium), fg::Filter::Nearest);
            }
            const fg::ImageHandle view_depth = builder.create_image(
                "godray depth", {VK_FORMAT_R32G32B32A32_SFLOAT, fg::SizeClass::OutputRelative, scale});
            d.view_depth = builder.write_storage("view_depth", view_depth);
        },
        [](const Data& d, fg::PassContext& context) {
            ComputePipelineDesc desc;
            desc.shader = ShaderVariant{"godrays/godray_depth.comp"}
                              .define("VKWATER_PER_PIXEL_MEDIUM", d.per_pixel_medium)
                              .file();
            const Pipeline& pipeline = context.pipeline(desc.shader, desc);
            context.bind(pipeline);
            context.dispatch(pipeline, d.view_depth);
        });
    return data.view_depth;
}

}  // namespace vkw::passes
