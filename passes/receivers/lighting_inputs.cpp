#include "passes/receivers/lighting_inputs.hpp"

#include "passes/caustics/caustics_camera_splats.hpp"
#include "passes/caustics/caustics_resolve.hpp"
#include "passes/common/frame_keys.hpp"
#include "passes/receivers/sun_shadow.hpp"
#include "passes/water/camera_medium.hpp"
#include "passes/water/scene_optics.hpp"

namespace vkw::passes {

void LightingInputs::declare(fg::PassBuilder& builder, const fg::Blackboard& blackboard, bool with_camera_medium) {
    constants = builder.uniform_buffer(blackboard.get(keys::kFrameConstants),
                                       VK_PIPELINE_STAGE_2_VERTEX_SHADER_BIT | VK_PIPELINE_STAGE_2_FRAGMENT_SHADER_BIT);
    optics = builder.read_storage(blackboard.get(keys::kSceneOptics));
    if (with_camera_medium && blackboard.has(keys::kCameraMedium)) {
        camera_medium = builder.sample(blackboard.get(keys::kCameraMedium), VK_PIPELINE_STAGE_2_FRAGMENT_SHADER_BIT);
    }
    if (blackboard.has(keys::kCausticMap)) {
        const CausticMap& caustics = blackboard.get(keys::kCausticMap);
        caustic_frame = builder.uniform_buffer(caustics.frame, VK_PIPELINE_STAGE_2_FRAGMENT_SHADER_BIT);
        caustic_map = builder.sample(caustics.irradiance, VK_PIPELINE_STAGE_2_FRAGMENT_SHADER_BIT);
    }
    if (blackboard.has(keys::kCameraCaustics)) {
        const CameraCaustics& caustics = blackboard.get(keys::kCameraCaustics);
        camera_caustic_receivers = builder.sample(caustics.receivers, VK_PIPELINE_STAGE_2_FRAGMENT_SHADER_BIT);
        camera_caustics = builder.sample(caustics.irradiance, VK_PIPELINE_STAGE_2_FRAGMENT_SHADER_BIT);
    }
    if (blackboard.has(keys::kSunShadow)) {
        sun_shadow.declare(builder, &blackboard.get(keys::kSunShadow), VK_PIPELINE_STAGE_2_FRAGMENT_SHADER_BIT);
    }
}

std::string LightingInputs::shader(const std::string& base) const {
    return base + (camera_medium ? ".per_pixel" : ".frame") + (caustic_map ? "_caustics" : "") +
           (camera_caustics ? "_camera_caustics" : "") + (sun_shadow ? "_shadow" : "");
}

void LightingInputs::add_bindings(const fg::PassContext& context, std::vector<fg::DescriptorBinding>& bindings) const {
    bindings.push_back(context.uniform_buffer(0, constants));
    bindings.push_back(context.storage_buffer(1, optics));
    if (camera_medium) bindings.push_back(context.sampled(3, *camera_medium));
    if (caustic_map) {
        bindings.push_back(context.uniform_buffer(4, *caustic_frame));
        bindings.push_back(context.sampled(5, *caustic_map));
    }
    if (camera_caustics) {
        bindings.push_back(context.sampled_nearest(4, *camera_caustic_receivers));
        bindings.push_back(context.sampled_nearest(5, *camera_caustics));
    }
    sun_shadow.add_bindings(context, bindings);
}

}  // namespace vkw::passes
