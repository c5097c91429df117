#include "passes/water/water_volume_stencil.hpp"

#include "engine/framegraph/pass_context.hpp"
#include "engine/scene/effects.hpp"
#include "passes/common/frame_keys.hpp"

namespace vkw::passes {
namespace {

// The surface's cells, the walls (4 R quads) and the bottom fan (4 R triangles).
uint32_t volume_vertex_count(uint32_t r) { return 6 * r * r + 24 * r + 12 * r; }

fg::ImageHandle add_stencil_pass(fg::FrameGraph& graph, fg::BufferHandle surface, uint32_t grid_resolution,
                                 float bottom_y) {
    struct Data {
        fg::BufferHandle constants, surface;
        fg::ImageHandle stencil;
    };
    const auto& data = graph.add_pass<Data>(
        "water volume stencil", fg::PassKind::Graphics,
        [&](fg::PassBuilder& builder, Data& d) {
            builder.serves(Effect::UnderwaterView);
            d.constants = builder.uniform_buffer(graph.blackboard().get(keys::kFrameConstants),
                                                 VK_PIPELINE_STAGE_2_VERTEX_SHADER_BIT);
            d.surface = builder.read_storage(surface, VK_PIPELINE_STAGE_2_VERTEX_SHADER_BIT);
            d.stencil = builder.create_image("water volume stencil", {VK_FORMAT_D32_SFLOAT_S8_UINT});
            d.stencil = builder.depth_stencil_attachment(d.stencil, fg::LoadOp::Clear, {.depth = 0.0f, .stencil = 0});
        },
        [grid_resolution, bottom_y](const Data& d, fg::PassContext& context) {
            GraphicsPipelineDesc desc;
            desc.vertex_shader = "water/water_volume.vert";
            desc.layout.bindings = {{0, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, 1, VK_SHADER_STAGE_VERTEX_BIT},
                                    {2, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, 1, VK_SHADER_STAGE_VERTEX_BIT}};
            struct Push {
                uint32_t resolution;
                float bottom_y;
            };
            desc.layout.push_constant_bytes = sizeof(Push);
            desc.cull_mode = VK_CULL_MODE_NONE;  // front and back faces both count
            desc.stencil_test = true;
            // Every crossing flips bit 0: its final value is the parity of the crossings.
            desc.stencil_front = {
                VK_STENCIL_OP_KEEP, VK_STENCIL_OP_INVERT, VK_STENCIL_OP_INVERT, VK_COMPARE_OP_ALWAYS, 1, 1, 0};
            desc.stencil_back = desc.stencil_front;
            const Pipeline& pipeline = context.pipeline("water volume stencil", desc);
            context.bind(pipeline, {context.uniform_buffer(0, d.constants), context.storage_buffer(2, d.surface)});
            context.push_constants(pipeline, Push{grid_resolution, bottom_y});
            vkCmdDraw(context.cmd(), volume_vertex_count(grid_resolution), 1, 0, 0);
        });
    return data.stencil;
}

fg::ImageHandle add_mask_pass(fg::FrameGraph& graph, fg::ImageHandle stencil) {
    struct Data {
        fg::ImageHandle stencil, mask;
    };
    const auto& data = graph.add_pass<Data>(
        "camera medium", fg::PassKind::Graphics,
        [&](fg::PassBuilder& builder, Data& d) {
            builder.serves(Effect::UnderwaterView);
            d.stencil = builder.depth_stencil_read_only(stencil);
            d.mask = builder.create_image("camera medium", {VK_FORMAT_R8_UNORM});
            d.mask = builder.color_attachment(d.mask, fg::LoadOp::Clear);
        },
        [](const Data&, fg::PassContext& context) {
            GraphicsPipelineDesc desc;
            desc.vertex_shader = "common/fullscreen.vert";
            desc.fragment_shader = "water/camera_medium_mask.frag";
            desc.stencil_test = true;
            // Odd crossing count: the ray starts in the water. Reads the stencil, writes none.
            desc.stencil_front = {
                VK_STENCIL_OP_KEEP, VK_STENCIL_OP_KEEP, VK_STENCIL_OP_KEEP, VK_COMPARE_OP_EQUAL, 1, 0, 1};
            desc.stencil_back = desc.stencil_front;
            const Pipeline& pipeline = context.pipeline("camera medium", desc);
            context.bind(pipeline, {});
            vkCmdDraw(context.cmd(), 3, 1, 0, 0);
        });
    return data.mask;
}

}  // namespace

void add_water_volume_stencil_passes(fg::FrameGraph& graph, fg::BufferHandle surface, uint32_t grid_resolution,
                                     double bottom_y) {
    const fg::ImageHandle stencil = add_stencil_pass(graph, surface, grid_resolution, static_cast<float>(bottom_y));
    graph.blackboard().put(keys::kCameraMedium, add_mask_pass(graph, stencil));
}

}  // namespace vkw::passes
