// add_godray_lines_passes (godrays_lines.hpp).
#include "passes/godrays/godrays_lines.hpp"

#include "engine/framegraph/pass_context.hpp"
#include "engine/scene/effects.hpp"
#include "passes/common/frame_keys.hpp"
#include "passes/common/zeroed_buffer.hpp"
#include "passes/water/camera_medium.hpp"

#include <shader_structs/godrays/godray_lines.comp.hpp>

#include <algorithm>

namespace vkw::passes {
namespace {

constexpr uint32_t kViews = 3;  // direct, mirrored, refracted: gl_GlobalInvocationID.z

// The push-constant block of shaders/godrays/godray_lines.comp, generated from its SPIR-V (tools/shader_structs).
using GodrayLinesPush = glsl::godray_lines_comp::Push;

}  // namespace

uint32_t godray_pyramid_levels(uint32_t width, uint32_t height) {
    // The coarsest level keeps four to eight pixels on the longer side: wider beams (next to the
    // camera) deposit there too, over more of its pixels, so that their light still varies across
    // the image as the directions it is seen from do.
    uint32_t levels = 1;
    while ((std::max(width, height) >> (levels + 2)) > 0) ++levels;
    return levels;
}

VkDeviceSize godray_pyramid_bytes(uint32_t width, uint32_t height) {
    VkDeviceSize pixels = 0;
    for (uint32_t level = 0; level < godray_pyramid_levels(width, height); ++level) {
        const uint32_t cell = 1u << level;
        pixels += VkDeviceSize{(width + cell - 1) / cell} * ((height + cell - 1) / cell);
    }
    return 2 * pixels * 3 * sizeof(uint64_t);  // the straight and the mirrored pyramid
}

fg::BufferHandle add_godray_lines_passes(fg::FrameGraph& graph, const GodrayLineInputs& inputs) {
    const VkDeviceSize bytes = godray_pyramid_bytes(inputs.width, inputs.height);

    const fg::BufferHandle cleared =
        add_zeroed_buffer_pass(graph, "godray clear", "godray radiance", bytes, Effect::VolumeCaustics);

    GodrayLinesPush push{};
    push.grid = inputs.grid;
    push.per_pixel_medium = graph.blackboard().has(keys::kCameraMedium) ? 1u : 0u;
    push.max_amplitude = static_cast<float>(inputs.max_amplitude);
    push.levels = static_cast<int32_t>(godray_pyramid_levels(inputs.width, inputs.height));
    struct Data {
        fg::BufferHandle radiance;
    };
    const auto& data = graph.add_pass<Data>(
        "godray lines", fg::PassKind::Compute,
        [&](fg::PassBuilder& builder, Data& d) {
            builder.serves(Effect::VolumeCaustics);
            builder.uniform_buffer("FrameConstants", graph.blackboard().get(keys::kFrameConstants));
            builder.read_storage("Beams", inputs.beams);
            builder.sample("view_depth", inputs.view_depth, fg::Filter::Nearest);
            d.radiance = builder.read_write_storage("Radiance", cleared);
        },
        [push](const Data&, fg::PassContext& context) {
            ComputePipelineDesc desc;
            desc.shader = "godrays/godray_lines.comp";
            const Pipeline& pipeline = context.pipeline("godray lines", desc);
            context.bind(pipeline);
            context.push_constants(pipeline, push);
            context.dispatch(pipeline, push.grid, push.grid, kViews);
        });
    return data.radiance;
}

}  // namespace vkw::passes
