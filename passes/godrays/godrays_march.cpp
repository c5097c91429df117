// add_godray_march_pass (godrays_march.hpp).
#include "passes/godrays/godrays_march.hpp"

#include "engine/core/errors.hpp"
#include "engine/framegraph/pass_context.hpp"
#include "engine/scene/effects.hpp"
#include "engine/vk/shader_variant.hpp"
#include "passes/caustics/caustics_resolve.hpp"
#include "passes/common/frame_keys.hpp"
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
    struct Data {
        fg::ImageHandle target;
        bool caustics = false;
        SunShadowReads shadow;
    };
    const auto& data = graph.add_pass<Data>(
        "godray march", fg::PassKind::Compute,
        [&](fg::PassBuilder& builder, Data& d) {
            builder.serves(Effect::VolumeCaustics);
            const fg::Blackboard& blackboard = graph.blackboard();
            builder.uniform_buffer("FrameConstants", blackboard.get(keys::kFrameConstants));
            builder.read_storage("Optics", blackboard.get(keys::kSceneOptics));
            builder.sample("view_depth", inputs.view_depth, fg::Filter::Nearest);
            d.caustics = blackboard.has(keys::kCausticMap);
            if (d.caustics) {
                builder.uniform_buffer("CausticMapBlock", blackboard.get(keys::kCausticMap).frame);
                builder.sample("caustic_map", blackboard.get(keys::kCausticMap).irradiance, fg::Filter::Nearest);
            }
            if (blackboard.has(keys::kSunShadow)) d.shadow.declare(builder, &blackboard.get(keys::kSunShadow));
            const fg::ImageHandle target = builder.create_image(
                "godray radiance image", {VK_FORMAT_R32G32B32A32_SFLOAT, fg::SizeClass::OutputRelative, inputs.scale});
            d.target = builder.write_storage("target", target);
        },
        [push](const Data& d, fg::PassContext& context) {
            const bool shadow = static_cast<bool>(d.shadow);
            ComputePipelineDesc desc;
            desc.shader = ShaderVariant{"godrays/godray_march.comp"}
                              .define("VKWATER_CAUSTICS", d.caustics)
                              .define("VKWATER_SUN_SHADOW", shadow)
                              .file();
            const Pipeline& pipeline = context.pipeline(desc.shader, desc);
            context.bind(pipeline);
            context.push_constants(pipeline, push);
            context.dispatch(pipeline, d.target);
        });
    return data.target;
}

}  // namespace vkw::passes
