#include "passes/sky/sky.hpp"

#include "engine/framegraph/pass_context.hpp"
#include "engine/vk/shader_variant.hpp"
#include "passes/common/frame_keys.hpp"
#include "passes/common/scene_depth.hpp"
#include "passes/water/camera_medium.hpp"
#include "passes/water/scene_optics.hpp"

#include <optional>

namespace vkw::passes {

void add_sky_pass(fg::FrameGraph& graph, bool infinite_water) {
    struct Data {
        fg::ImageHandle hdr;
        std::optional<fg::ImageHandle> depth;  // the scene depth, where an opaque pass drew
        bool per_pixel_medium = false;         // the camera-medium split runs
        bool infinite_water = false;
    };
    const auto& data = graph.add_pass<Data>(
        "sky", fg::PassKind::Graphics,
        [&](fg::PassBuilder& builder, Data& d) {
            builder.uniform_buffer("FrameConstants", graph.blackboard().get(keys::kFrameConstants));
            d.hdr = hdr_colour_attachment(builder, graph.blackboard());
            if (graph.blackboard().has(keys::kSceneDepth)) {
                d.depth = builder.depth_stencil_read_only(graph.blackboard().get(keys::kSceneDepth));
            }
            d.per_pixel_medium = graph.blackboard().has(keys::kCameraMedium);
            if (d.per_pixel_medium) builder.sample("camera_medium_mask", graph.blackboard().get(keys::kCameraMedium));
            d.infinite_water = infinite_water;
            if (infinite_water) builder.read_storage("Optics", graph.blackboard().get(keys::kSceneOptics));
        },
        [](const Data& d, fg::PassContext& context) {
            GraphicsPipelineDesc desc;
            desc.vertex_shader = "common/fullscreen.vert";
            desc.fragment_shader = ShaderVariant{"sky/sky.frag"}
                                       .define("VKWATER_PER_PIXEL_MEDIUM", d.per_pixel_medium)
                                       .define("VKWATER_INFINITE_WATER", d.infinite_water)
                                       .file();
            // The full-screen triangle lies on the far plane (depth 0, reversed Z): it passes only
            // where the scene depth is still the clear value, the pixels no opaque pass covered.
            desc.depth_test = d.depth.has_value();
            desc.depth_compare = VK_COMPARE_OP_EQUAL;
            const Pipeline& pipeline = context.pipeline(desc.fragment_shader, desc);
            context.bind(pipeline);
            vkCmdDraw(context.cmd(), 3, 1, 0, 0);
        });
    graph.blackboard().put(keys::kHdrColor, data.hdr);
}

}  // namespace vkw::passes
