// add_godray_march_pass (godrays_march.hpp).
#include "passes/godrays/godrays_march.hpp"

#include "engine/core/errors.hpp"
#include "engine/framegraph/pass_context.hpp"
#include "engine/scene/effects.hpp"
#include "passes/caustics/caustics_resolve.hpp"
#include "passes/common/frame_keys.hpp"
#include "passes/receivers/sun_shadow.hpp"
#include "passes/water/scene_optics.hpp"

#include <algorithm>
#include <optional>
#include <string>
#include <vector>

namespace vkw::passes {
namespace {

// Mirrors the push constants of shaders/godrays/godray_march.comp.
struct GodrayMarchPush {
    uint32_t steps;
    float max_amplitude, max_depth, pad;
};

}  // namespace

fg::ImageHandle add_godray_march_pass(fg::FrameGraph& graph, const GodrayMarchInputs& inputs) {
    if (inputs.steps < 1 || inputs.steps > 4096) {
        throw InternalError("godray march: " + std::to_string(inputs.steps) + " steps (accepted: 1..4096)");
    }
    const GodrayMarchPush push{inputs.steps, static_cast<float>(inputs.max_amplitude),
                               static_cast<float>(std::min(inputs.max_depth, 1e30)), 0.0f};
    struct Data {
        fg::BufferHandle constants, optics;
        fg::ImageHandle view_depth, target;
        std::optional<fg::BufferHandle> caustic_frame;
        std::optional<fg::ImageHandle> caustic_map;
        SunShadowReads shadow;
    };
    const auto& data = graph.add_pass<Data>(
        "godray march", fg::PassKind::Compute,
        [&](fg::PassBuilder& builder, Data& d) {
            builder.serves(Effect::VolumeCaustics);
            const VkPipelineStageFlags2 stage = VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT;
            const fg::Blackboard& blackboard = graph.blackboard();
            d.constants = builder.uniform_buffer(blackboard.get(keys::kFrameConstants), stage);
            d.optics = builder.read_storage(blackboard.get(keys::kSceneOptics), stage);
            d.view_depth = builder.sample(inputs.view_depth, stage);
            if (blackboard.has(keys::kCausticMap)) {
                d.caustic_frame = builder.uniform_buffer(blackboard.get(keys::kCausticMap).frame, stage);
                d.caustic_map = builder.sample(blackboard.get(keys::kCausticMap).irradiance, stage);
            }
            if (blackboard.has(keys::kSunShadow)) d.shadow.declare(builder, &blackboard.get(keys::kSunShadow), stage);
            fg::ImageInfo info;
            info.format = VK_FORMAT_R32G32B32A32_SFLOAT;
            info.scale = inputs.scale;
            d.target = builder.write_storage(builder.create_image("godray radiance image", info), stage);
        },
        [push](const Data& d, fg::PassContext& context) {
            const bool shadow = static_cast<bool>(d.shadow);
            const std::string variant = d.caustic_map && shadow ? "caustics_shadow"
                                        : d.caustic_map         ? "caustics"
                                        : shadow                ? "shadow"
                                                                : "plain";
            ComputePipelineDesc desc;
            desc.shader = "godrays/godray_march.comp." + variant;
            std::vector<fg::DescriptorBinding> bindings{
                context.uniform_buffer(0, d.constants), context.storage_buffer(1, d.optics),
                context.sampled_nearest(2, d.view_depth), context.storage_image(3, d.target)};
            if (d.caustic_map) {
                bindings.push_back(context.uniform_buffer(4, *d.caustic_frame));
                bindings.push_back(context.sampled_nearest(5, *d.caustic_map));
            }
            d.shadow.add_bindings(context, bindings);
            const Pipeline& pipeline = context.pipeline(desc.shader, desc);
            context.bind(pipeline, bindings);
            context.push_constants(pipeline, push);
            const VkExtent2D size = context.extent(d.target);
            vkCmdDispatch(context.cmd(), (size.width + 7) / 8, (size.height + 7) / 8, 1);
        });
    return data.target;
}

}  // namespace vkw::passes
