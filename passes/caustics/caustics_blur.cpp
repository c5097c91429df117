// add_caustic_blur_pass (caustics_blur.hpp).
#include "passes/caustics/caustics_blur.hpp"

#include "engine/framegraph/pass_context.hpp"
#include "engine/scene/effects.hpp"
#include "passes/caustics/caustics_map_frame.hpp"

namespace vkw::passes {
namespace {

constexpr uint32_t kGroupSide = 8;  // local_size of caustic_blur.comp

// Mirrors the push constants of shaders/caustics/caustic_blur.comp.
struct BlurPush {
    int32_t size[2];
    int32_t axis[2];
    float radius;
    float flat_sum;
    uint32_t first_axis;
    float pad;
};

}  // namespace

CausticMap add_caustic_blur_pass(fg::FrameGraph& graph, const CausticMap& map, const CausticInputs& inputs,
                                 double radius) {
    const CausticMapFrame frame = fit_caustic_map(inputs);
    double flat_sum = 0.0;
    for (int c = 0; c < 3; ++c) flat_sum += frame.flat_texel_flux[c] / frame.texel_area;
    // A sun whose flat-water light is 0 (night, or a black sun) leaves nothing to blur; any
    // positive unit keeps the shader's arithmetic finite.
    if (!(flat_sum > 0.0)) flat_sum = 1.0;
    const fg::ImageInfo info = caustic_map_image(frame);

    fg::ImageHandle image = map.irradiance;
    for (const bool first : {true, false}) {
        struct Data {
            fg::ImageHandle source, target;
        };
        const BlurPush push{{int32_t(frame.width), int32_t(frame.height)},
                            {first ? 1 : 0, first ? 0 : 1},
                            float(radius),
                            float(flat_sum),
                            first ? 1u : 0u,
                            0.0f};
        const char* name = first ? "caustic blur x" : "caustic blur y";
        const auto& data = graph.add_pass<Data>(
            name, fg::PassKind::Compute,
            [&](fg::PassBuilder& builder, Data& d) {
                builder.serves(Effect::CausticBlur);
                const VkPipelineStageFlags2 stage = VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT;
                d.source = builder.read_storage(image, stage);
                d.target = builder.write_storage(builder.create_image(std::string(name) + " target", info), stage);
            },
            [push](const Data& d, fg::PassContext& context) {
                ComputePipelineDesc desc;
                desc.shader = "caustics/caustic_blur.comp";
                const Pipeline& pipeline = context.pipeline("caustic blur", desc);
                context.bind(pipeline, {context.storage_image(0, d.source), context.storage_image(1, d.target)});
                context.push_constants(pipeline, push);
                vkCmdDispatch(context.cmd(), (uint32_t(push.size[0]) + kGroupSide - 1) / kGroupSide,
                              (uint32_t(push.size[1]) + kGroupSide - 1) / kGroupSide, 1);
            });
        image = data.target;
    }
    return {image, map.frame};
}

}  // namespace vkw::passes
