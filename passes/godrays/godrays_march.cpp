// add_godray_march_pass (godrays_march.hpp).
#include "passes/godrays/godrays_march.hpp"

#include "engine/core/errors.hpp"
#include "engine/scene/effects.hpp"
#include "engine/vk/shader_variant.hpp"
#include "passes/caustics/caustics_resolve.hpp"
#include "passes/common/frame_keys.hpp"
#include "passes/common/image_compute_pass.hpp"
#include "passes/receivers/sun_shadow.hpp"
#include "passes/water/scene_optics.hpp"

#include <shader_structs/godrays/godray_march.comp.hpp>

#include <algorithm>
#include <string>

namespace vkw::passes {
namespace {

// The push-constant block of shaders/godrays/godray_march.comp, generated from its SPIR-V (tools/shader_structs).
using GodrayMarchPush = glsl::godray_march_comp::Push;

}  // namespace

fg::ImageHandle add_godray_march_pass(fg::FrameGraph& graph, const GodrayMarchInputs& inputs) {
    if (inputs.steps < 1 || inputs.steps > 4096) {
        throw InternalError("godray march: " + std::to_string(inputs.steps) + " steps (accepted: 1..4096)");
    }
    const GodrayMarchPush push{inputs.steps, static_cast<float>(inputs.max_amplitude),
                               static_cast<float>(std::min(inputs.max_depth, 1e30)), 0.0f};
    const ImageComputePass pass{"godray march",
                                "godray radiance image",
                                {VK_FORMAT_R32G32B32A32_SFLOAT, fg::SizeClass::OutputRelative, inputs.scale}};
    return add_image_compute_pass(graph, pass, push, [&](fg::PassBuilder& builder) {
        builder.serves(Effect::VolumeCaustics);
        const fg::Blackboard& blackboard = graph.blackboard();
        builder.uniform_buffer("FrameConstants", blackboard.get(keys::kFrameConstants));
        builder.read_storage("Optics", blackboard.get(keys::kSceneOptics));
        builder.sample("view_depth", inputs.view_depth, fg::Filter::Nearest);
        const bool caustics = blackboard.has(keys::kCausticMap);
        if (caustics) {
            builder.uniform_buffer("CausticMapBlock", blackboard.get(keys::kCausticMap).frame);
            builder.sample("caustic_map", blackboard.get(keys::kCausticMap).irradiance, fg::Filter::Nearest);
        }
        SunShadowReads shadow;
        if (blackboard.has(keys::kSunShadow)) shadow.declare(builder, &blackboard.get(keys::kSunShadow));
        return ShaderVariant{"godrays/godray_march.comp"}
            .define("VKWATER_CAUSTICS", caustics)
            .define("VKWATER_SUN_SHADOW", static_cast<bool>(shadow))
            .file();
    });
}

}  // namespace vkw::passes
