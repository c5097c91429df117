#include "passes/water_shading.hpp"

#include "engine/framegraph/pass_context.hpp"
#include "engine/render/blackboard_keys.hpp"

#include <optional>

namespace vkw::passes {

void add_water_shading_pass(fg::FrameGraph& graph, fg::BufferHandle surface, uint32_t grid_resolution) {
    struct Data {
        fg::BufferHandle constants, optics, surface;
        fg::ImageHandle hdr, depth;
        std::optional<fg::ImageHandle> camera_medium;  // the stencil split's mask, while it runs
    };
    constexpr VkPipelineStageFlags2 kVertexAndFragment =
        VK_PIPELINE_STAGE_2_VERTEX_SHADER_BIT | VK_PIPELINE_STAGE_2_FRAGMENT_SHADER_BIT;
    const auto& data = graph.add_pass<Data>(
        "water", fg::PassKind::Graphics,
        [&](fg::PassBuilder& builder, Data& d) {
            builder.serves(fg::Effect::Water);
            d.constants = builder.uniform_buffer(graph.blackboard().get(keys::kFrameConstants), kVertexAndFragment);
            d.optics = builder.read_storage(graph.blackboard().get(keys::kSceneOptics));
            d.surface = builder.read_storage(surface, VK_PIPELINE_STAGE_2_VERTEX_SHADER_BIT);
            d.hdr = builder.color_attachment(graph.blackboard().get(keys::kHdrColor), fg::LoadOp::Load);
            d.depth = builder.depth_stencil_attachment(graph.blackboard().get(keys::kSceneDepth), fg::LoadOp::Load);
            if (graph.blackboard().has(keys::kCameraMedium)) {
                d.camera_medium = builder.sample(graph.blackboard().get(keys::kCameraMedium),
                                                 VK_PIPELINE_STAGE_2_FRAGMENT_SHADER_BIT);
            }
        },
        [grid_resolution](const Data& d, fg::PassContext& context) {
            GraphicsPipelineDesc desc;
            desc.vertex_shader = "water_shading/water_surface.vert";
            desc.fragment_shader = d.camera_medium ? "water_shading/water_surface_per_pixel.frag"
                                                   : "water_shading/water_surface.frag";
            constexpr VkShaderStageFlags both = VK_SHADER_STAGE_VERTEX_BIT | VK_SHADER_STAGE_FRAGMENT_BIT;
            desc.layout.bindings = {{0, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, 1, both},
                                    {1, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, 1, VK_SHADER_STAGE_FRAGMENT_BIT},
                                    {2, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, 1, VK_SHADER_STAGE_VERTEX_BIT}};
            desc.layout.push_constant_bytes = sizeof(uint32_t);
            if (d.camera_medium) {
                desc.layout.bindings.push_back({3, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, 1,
                                                VK_SHADER_STAGE_FRAGMENT_BIT});
            }
            desc.depth_test = true;
            desc.depth_write = true;
            const Pipeline& pipeline = context.pipeline(d.camera_medium ? "water per-pixel medium" : "water", desc);
            const fg::DescriptorBinding constants = context.uniform_buffer(0, d.constants);
            const fg::DescriptorBinding optics = context.storage_buffer(1, d.optics);
            const fg::DescriptorBinding vertices = context.storage_buffer(2, d.surface);
            if (d.camera_medium) {
                context.bind(pipeline, {constants, optics, vertices, context.sampled(3, *d.camera_medium)});
            } else {
                context.bind(pipeline, {constants, optics, vertices});
            }
            context.push_constants(pipeline, grid_resolution);
            vkCmdDraw(context.cmd(), 6 * grid_resolution * grid_resolution, 1, 0, 0);
        });
    graph.blackboard().put(keys::kHdrColor, data.hdr);
    graph.blackboard().put(keys::kSceneDepth, data.depth);
}

}  // namespace vkw::passes
