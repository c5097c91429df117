// add_godray_blur_pass (godrays_blur.hpp).
#include "passes/godrays/godrays_blur.hpp"

#include "engine/framegraph/pass_context.hpp"
#include "engine/scene/effects.hpp"

#include <shader_structs/godrays/godray_blur.comp.hpp>

namespace vkw::passes {

using glsl::godray_blur_comp::Push;

fg::ImageHandle add_godray_blur_pass(fg::FrameGraph& graph, fg::ImageHandle image, fg::ImageHandle view_depth,
                                     float scale, BlurAxis axis) {
    const bool along_x = axis == BlurAxis::X;
    struct Data {
        fg::ImageHandle target;
    };
    const auto& data = graph.add_pass<Data>(
        along_x ? "godray blur x" : "godray blur y", fg::PassKind::Compute,
        [&](fg::PassBuilder& builder, Data& d) {
            builder.serves(Effect::VolumeCaustics);
            builder.sample("source", image, fg::Filter::Nearest);
            builder.sample("view_depth", view_depth, fg::Filter::Nearest);
            const fg::ImageHandle target =
                builder.create_image(along_x ? "godray blurred x" : "godray blurred",
                                     {VK_FORMAT_R32G32B32A32_SFLOAT, fg::SizeClass::OutputRelative, scale});
            d.target = builder.write_storage("target", target);
        },
        [along_x](const Data& d, fg::PassContext& context) {
            const Pipeline& pipeline = context.pipeline("godray blur", ComputePipelineDesc{"godrays/godray_blur.comp"});
            context.bind(pipeline);
            context.push_constants(pipeline, Push{glm::ivec2(along_x ? 1 : 0, along_x ? 0 : 1)});
            context.dispatch(pipeline, d.target);
        });
    return data.target;
}

}  // namespace vkw::passes
