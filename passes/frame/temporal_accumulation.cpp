// Temporal accumulation (temporal_accumulation.hpp).
#include "passes/frame/temporal_accumulation.hpp"

#include "engine/framegraph/pass_context.hpp"
#include "engine/scene/pixel_filter.hpp"
#include "passes/common/frame_keys.hpp"
#include "passes/common/whole_image_copy.hpp"

#include <shader_structs/frame/temporal_accumulate.comp.hpp>

#include <array>

namespace vkw::passes {
namespace {

using TemporalPush = glsl::temporal_accumulate_comp::Push;

// Between frames the history waits where the copy of the accumulated colour left it.
fg::AccessState history_state() { return fg::access_state(fg::Use::TransferDst, fg::PassKind::Transfer); }

}  // namespace

glm::dvec2 temporal_jitter(uint32_t index) {
    // Frame f visits the stratum whose entry in the 4 x 4 Bayer matrix is f, as row * 4 + column:
    //    0  8  2 10
    //   12  4 14  6
    //    3 11  1  9
    //   15  7 13  5
    static constexpr std::array<uint32_t, kTemporalJitterCycle> kStratumOfFrame = {0, 10, 2, 8, 5, 15, 7, 13,
                                                                                   1, 11, 3, 9, 4, 14, 6, 12};
    static const PixelFilter kBox = pixel_filter_from_spp(kTemporalJitterCycle);
    return kBox.stratum_centre(kStratumOfFrame[index % kTemporalJitterCycle]);
}

glm::dmat4 temporal_reprojection(const glm::dmat4& previous_view_proj, const glm::dmat4& view_proj) {
    return previous_view_proj * glm::inverse(view_proj);
}

fg::ImageHandle add_temporal_accumulation(fg::FrameGraph& graph, fg::ImageHandle colour, TemporalInputs inputs) {
    inputs.history.initial = inputs.first ? fg::AccessState{} : history_state();
    inputs.history.final_state = history_state();
    const fg::ImageHandle history = graph.import_image("temporal history", inputs.history);
    const TemporalPush push{inputs.reprojection, inputs.blend, inputs.first ? 1u : 0u, inputs.clamp_history ? 1u : 0u,
                            inputs.camera_still ? 1u : 0u};
    struct Data {
        fg::ImageHandle accumulated;
    };
    const auto& data = graph.add_pass<Data>(
        "temporal accumulation", fg::PassKind::Compute,
        [&](fg::PassBuilder& builder, Data& d) {
            builder.read_storage("current", colour);
            builder.sample("scene_depth", graph.blackboard().get(keys::kSceneDepth), fg::Filter::Nearest);
            builder.read_storage("history", history);
            // The history's size: the output's, which the scene's passes render below at a resolution scale.
            const fg::ImageInfo info{VK_FORMAT_R32G32B32A32_SFLOAT, fg::SizeClass::Absolute, 1.0f, inputs.history.width,
                                     inputs.history.height};
            d.accumulated = builder.write_storage("accumulated", builder.create_image("accumulated colour", info));
        },
        [push](const Data& d, fg::PassContext& context) {
            const Pipeline& pipeline =
                context.pipeline("temporal accumulation", ComputePipelineDesc{"frame/temporal_accumulate.comp"});
            context.bind(pipeline);
            context.push_constants(pipeline, push);
            context.dispatch(pipeline, d.accumulated);
        });
    add_whole_image_copy_pass(graph, "temporal history copy", data.accumulated, history);
    return data.accumulated;
}

}  // namespace vkw::passes
