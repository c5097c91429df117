// add_godray_depth_pass (godrays_depth.hpp).
#include "passes/godrays/godrays_depth.hpp"

#include "engine/scene/effects.hpp"
#include "engine/vk/shader_variant.hpp"
#include "passes/common/frame_keys.hpp"
#include "passes/common/image_compute_pass.hpp"
#include "passes/water/camera_medium.hpp"

namespace vkw::passes {

fg::ImageHandle add_godray_depth_pass(fg::FrameGraph& graph, float scale) {
    const ImageComputePass pass{"godray depth",
                                "godray depth",
                                {VK_FORMAT_R32G32B32A32_SFLOAT, fg::SizeClass::OutputRelative, scale},
                                "view_depth"};
    return add_image_compute_pass(graph, pass, NoPush{}, [&](fg::PassBuilder& builder) {
        builder.serves(Effect::VolumeCaustics);
        builder.uniform_buffer("FrameConstants", graph.blackboard().get(keys::kFrameConstants));
        builder.sample("scene_depth", graph.blackboard().get(keys::kSceneDepth), fg::Filter::Nearest);
        const bool per_pixel_medium = graph.blackboard().has(keys::kCameraMedium);
        if (per_pixel_medium) {
            builder.sample("camera_medium_mask", graph.blackboard().get(keys::kCameraMedium), fg::Filter::Nearest);
        }
        return ShaderVariant{"godrays/godray_depth.comp"}.define("VKWATER_PER_PIXEL_MEDIUM", per_pixel_medium).file();
    });
}

}  // namespace vkw::passes
