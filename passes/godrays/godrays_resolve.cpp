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
        fg::BufferHandle constants, radiance;
        fg::ImageHandle view_depth, image;
    };
    const auto& data = graph.add_pass<Data>(
        "godray resolve", fg::PassKind::Compute,
        [&](fg::PassBuilder& builder, Data& d) {
            builder.serves(Effect::VolumeCaustics);
            const VkPipelineStageFlags2 stage = VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT;
            d.constants = builder.uniform_buffer(graph.blackboard().get(keys::kFrameConstants), stage);
            d.radiance = builder.read_storage(radiance, stage);
            d.view_depth = builder.sample(view_depth, stage);
            fg::ImageInfo info;
            info.format = VK_FORMAT_R32G32B32A32_SFLOAT;
            info.scale = scale;
            d.image = builder.write_storage(builder.create_image("godray radiance image", info), stage);
        },
        [levels](const Data& d, fg::PassContext& context) {
            ComputePipelineDesc desc;
            desc.shader = "godrays/godray_resolve.comp";
            const Pipeline& pipeline = context.pipeline("godray resolve", desc);
            context.bind(pipeline, {context.uniform_buffer(0, d.constants), context.storage_buffer(1, d.radiance),
                                    context.sampled_nearest(2, d.view_depth), context.storage_image(3, d.image)});
            context.push_constants(pipeline, levels);
            const VkExtent2D size = context.extent(d.image);
            vkCmdDispatch(context.cmd(), (size.width + 7) / 8, (size.height + 7) / 8, 1);
        });
    return data.image;
}

}  // namespace vkw::passes
