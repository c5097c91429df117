// add_godray_blur_pass (godrays_blur.hpp).
#include "passes/godrays/godrays_blur.hpp"

#include "engine/framegraph/pass_context.hpp"
#include "engine/scene/effects.hpp"

namespace vkw::passes {

fg::ImageHandle add_godray_blur_pass(fg::FrameGraph& graph, fg::ImageHandle image, fg::ImageHandle view_depth,
                                     float scale, BlurAxis axis) {
    const bool along_x = axis == BlurAxis::X;
    struct Data {
        fg::ImageHandle source, view_depth, target;
    };
    const auto& data = graph.add_pass<Data>(
        along_x ? "godray blur x" : "godray blur y", fg::PassKind::Compute,
        [&](fg::PassBuilder& builder, Data& d) {
            builder.serves(Effect::VolumeCaustics);
            const VkPipelineStageFlags2 stage = VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT;
            d.source = builder.sample(image, stage);
            d.view_depth = builder.sample(view_depth, stage);
            fg::ImageInfo info;
            info.format = VK_FORMAT_R32G32B32A32_SFLOAT;
            info.scale = scale;
            d.target = builder.write_storage(
                builder.create_image(along_x ? "godray blurred x" : "godray blurred", info), stage);
        },
        [along_x](const Data& d, fg::PassContext& context) {
            ComputePipelineDesc desc;
            desc.shader = "godrays/godray_blur.comp";
            const Pipeline& pipeline = context.pipeline("godray blur", desc);
            context.bind(pipeline, {context.sampled_nearest(1, d.source), context.sampled_nearest(2, d.view_depth),
                                    context.storage_image(3, d.target)});
            const int32_t step[2] = {along_x ? 1 : 0, along_x ? 0 : 1};
            context.push_constants(pipeline, step, sizeof step);
            const VkExtent2D size = context.extent(d.target);
            vkCmdDispatch(context.cmd(), (size.width + 7) / 8, (size.height + 7) / 8, 1);
        });
    return data.target;
}

}  // namespace vkw::passes
