// add_godray_resolve_pass (godrays_resolve.hpp).
#include "passes/godrays/godrays_resolve.hpp"

#include "engine/framegraph/pass_context.hpp"
#include "engine/scene/effects.hpp"
#include "passes/common/frame_keys.hpp"
#include "passes/godrays/godrays_lines.hpp"

namespace vkw::passes {

fg::ImageHandle add_godray_resolve_pass(fg::FrameGraph& graph, fg::BufferHandle radiance, fg::ImageHandle view_depth,
                                        float scale, uint32_t width, uint32_t height) {
    const auto levels = static_cast<int32_t>(godray_pyramid_levels(width, height));
    struct Data {
        fg::ImageHandle image;
    };
    const auto& data = graph.add_pass<Data>(
        "godray resolve", fg::PassKind::Compute,
        [&](fg::PassBuilder& builder, Data& d) {
            builder.serves(Effect::VolumeCaustics);
            builder.uniform_buffer("FrameConstants", graph.blackboard().get(keys::kFrameConstants));
            builder.read_storage("Radiance", radiance);
            builder.sample("view_depth", view_depth, fg::Filter::Nearest);
            const fg::ImageHandle image = builder.create_image(
                "godray radiance image", {VK_FORMAT_R32G32B32A32_SFLOAT, fg::SizeClass::OutputRelative, scale});
            d.image = builder.write_storage("target", image);
        },
        [levels](const Data& d, fg::PassContext& context) {
            const Pipeline& pipeline =
                context.pipeline("godray resolve", ComputePipelineDesc{"godrays/godray_resolve.comp"});
            context.bind(pipeline);
            context.push_constants(pipeline, levels);
            context.dispatch(pipeline, d.image);
        });
    return data.image;
}

}  // namespace vkw::passes
