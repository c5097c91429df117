#include "passes/receivers/lighting_inputs.hpp"

#include "passes/caustics/caustics_camera_splats.hpp"
#include "passes/caustics/caustics_resolve.hpp"
#include "passes/common/frame_keys.hpp"
#include "passes/receivers/sun_shadow.hpp"
#include "passes/water/camera_medium.hpp"
#include "passes/water/scene_optics.hpp"

namespace vkw::passes {

void LightingInputs::declare(fg::PassBuilder& builder, const fg::Blackboard& blackboard, bool with_camera_medium) {
    constexpr VkPipelineStageFlags2 fragment = VK_PIPELINE_STAGE_2_FRAGMENT_SHADER_BIT;
    builder.uniform_buffer("FrameConstants", blackboard.get(keys::kFrameConstants),
                           VK_PIPELINE_STAGE_2_VERTEX_SHADER_BIT | fragment);
    builder.read_storage("Optics", blackboard.get(keys::kSceneOptics));
    camera_medium = with_camera_medium && blackboard.has(keys::kCameraMedium);
    if (camera_medium) {
        builder.sample("camera_medium_mask", blackboard.get(keys::kCameraMedium), fg::Filter::Linear, fragment);
    }
    caustic_map = blackboard.has(keys::kCausticMap);
    if (caustic_map) {
        const CausticMap& caustics = blackboard.get(keys::kCausticMap);
        builder.uniform_buffer("CausticMapBlock", caustics.frame, fragment);
        builder.sample("caustic_map", caustics.irradiance, fg::Filter::Linear, fragment);
    }
    camera_caustics = blackboard.has(keys::kCameraCaustics);
    if (camera_caustics) {
        const CameraCaustics& caustics = blackboard.get(keys::kCameraCaustics);
        builder.sample("caustic_receivers", caustics.receivers, fg::Filter::Nearest, fragment);
        builder.sample("camera_caustics", caustics.irradiance, fg::Filter::Nearest, fragment);
    }
    if (blackboard.has(keys::kSunShadow)) sun_shadow.declare(builder, &blackboard.get(keys::kSunShadow), fragment);
}

ShaderVariant LightingInputs::shader(const std::string& source) const {
    return ShaderVariant{source}
        .define("VKWATER_PER_PIXEL_MEDIUM", camera_medium)
        .define("VKWATER_CAUSTICS", caustic_map)
        .define("VKWATER_CAMERA_CAUSTICS", camera_caustics)
        .define("VKWATER_SUN_SHADOW", static_cast<bool>(sun_shadow));
}

}  // namespace vkw::passes
