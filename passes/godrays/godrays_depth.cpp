// add_godray_depth_pass (godrays_depth.hpp).
#include "passes/godrays/godrays_depth.hpp"

#include "engine/framegraph/pass_context.hpp"
#include "engine/scene/effects.hpp"
#include "passes/common/frame_keys.hpp"
#include "passes/water/camera_medium.hpp"

#include <optional>
#include <vector>

namespace vkw::passes {

fg::ImageHandle add_godray_depth_pass(fg::FrameGraph& graph, float scale) {
    struct Data {
        fg::BufferHandle constants;
        fg::ImageHandle scene_depth, view_depth;
        std::optional<fg::ImageHandle> camera_medium;
    };
    const auto& data = graph.add_pass<Data>(
        "godray depth", fg::PassKind::Compute,
        [&](fg::PassBuilder& builder, Data& d) {
            builder.serves(Effect::VolumeCaustics);
            const VkPipelineStageFlags2 stage = VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT;
            d.constants = builder.uniform_buffer(graph.blackboard().get(keys::kFrameConstants), stage);
            d.scene_depth = builder.sample(graph.blackboard().get(keys::kSceneDepth), stage);
            if (graph.blackboard().has(keys::kCameraMedium)) {
                d.camera_medium = builder.sample(graph.blackboard().get(keys::kCameraMedium), stage);
            }
            fg::ImageInfo info;
            info.format = VK_FORMAT_R32G32B32A32_SFLOAT;
            info.scale = scale;
            d.view_depth = builder.write_storage(builder.create_image("godray depth", info), stage);
        },
        [](const Data& d, fg::PassContext& context) {
            ComputePipelineDesc desc;
            desc.shader = d.camera_medium ? "godrays/godray_depth.comp.per_pixel" : "godrays/godray_depth.comp.frame";
            std::vector<fg::DescriptorBinding> bindings{context.uniform_buffer(0, d.constants),
                                                        context.sampled_nearest(1, d.scene_depth),
                                                        context.storage_image(2, d.view_depth)};
            if (d.camera_medium) bindings.push_back(context.sampled_nearest(3, *d.camera_medium));
            const Pipeline& pipeline = context.pipeline(desc.shader, desc);
            context.bind(pipeline, bindings);
            const VkExtent2D size = context.extent(d.view_depth);
            vkCmdDispatch(context.cmd(), (size.width + 7) / 8, (size.height + 7) / 8, 1);
        });
    return data.view_depth;
}

}  // namespace vkw::passes
