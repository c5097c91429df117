#include "passes/floor.hpp"

#include "engine/framegraph/pass_context.hpp"
#include "engine/render/blackboard_keys.hpp"

#include <optional>

namespace vkw::passes {

void add_floor_pass(fg::FrameGraph& graph) {
    struct Data {
        fg::BufferHandle constants;
        fg::BufferHandle optics;
        fg::ImageHandle hdr;
        fg::ImageHandle depth;
        std::optional<fg::ImageHandle> camera_medium;  // the stencil split's mask, while it runs
    };
    const auto& data = graph.add_pass<Data>(
        "floor", fg::PassKind::Graphics,
        [&](fg::PassBuilder& builder, Data& d) {
            d.constants = builder.uniform_buffer(graph.blackboard().get(keys::kFrameConstants),
                                                 VK_PIPELINE_STAGE_2_VERTEX_SHADER_BIT |
                                                     VK_PIPELINE_STAGE_2_FRAGMENT_SHADER_BIT);
            d.optics = builder.read_storage(graph.blackboard().get(keys::kSceneOptics));
            d.hdr = builder.color_attachment(graph.blackboard().get(keys::kHdrColor), fg::LoadOp::Load);
            d.depth = builder.create_image("scene depth", {VK_FORMAT_D32_SFLOAT});
            d.depth = builder.depth_stencil_attachment(d.depth, fg::LoadOp::Clear, {.depth = 0.0f});
            if (graph.blackboard().has(keys::kCameraMedium)) {
                d.camera_medium = builder.sample(graph.blackboard().get(keys::kCameraMedium),
                                                 VK_PIPELINE_STAGE_2_FRAGMENT_SHADER_BIT);
            }
        },
        [](const Data& d, fg::PassContext& context) {
            GraphicsPipelineDesc desc;
            desc.vertex_shader = "receivers/floor.vert";
            desc.fragment_shader = d.camera_medium ? "receivers/floor_per_pixel.frag" : "receivers/floor.frag";
            desc.layout.bindings = {
                {0, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, 1, VK_SHADER_STAGE_VERTEX_BIT | VK_SHADER_STAGE_FRAGMENT_BIT},
                {1, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, 1, VK_SHADER_STAGE_FRAGMENT_BIT}};
            if (d.camera_medium) {
                desc.layout.bindings.push_back({3, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, 1,
                                                VK_SHADER_STAGE_FRAGMENT_BIT});
            }
            desc.depth_test = true;
            desc.depth_write = true;
            const Pipeline& pipeline = context.pipeline(d.camera_medium ? "floor per-pixel medium" : "floor", desc);
            const fg::DescriptorBinding constants = context.uniform_buffer(0, d.constants);
            const fg::DescriptorBinding optics = context.storage_buffer(1, d.optics);
            if (d.camera_medium) {
                context.bind(pipeline, {constants, optics, context.sampled(3, *d.camera_medium)});
            } else {
                context.bind(pipeline, {constants, optics});
            }
            vkCmdDraw(context.cmd(), 6, 1, 0, 0);
        });
    graph.blackboard().put(keys::kHdrColor, data.hdr);
    graph.blackboard().put(keys::kSceneDepth, data.depth);
}

}  // namespace vkw::passes
