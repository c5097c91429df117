// add_godray_resolve_pass (godrays_resolve.hpp).
#include "passes/godrays/godrays_resolve.hpp"

#include "engine/scene/effects.hpp"
#include "passes/common/frame_keys.hpp"
#include "passes/common/image_compute_pass.hpp"
#include "passes/godrays/godrays_lines.hpp"

namespace vkw::passes {

fg::ImageHandle add_godray_resolve_pass(fg::FrameGraph& graph, fg::BufferHandle radiance, fg::ImageHandle view_depth,
                                        float scale, uint32_t width, uint32_t height) {
    const auto levels = static_cast<int32_t>(godray_pyramid_levels(width, height));
    const ImageComputePass pass{"godray resolve",
                                "godray radiance image",
                                {VK_FORMAT_R32G32B32A32_SFLOAT, fg::SizeClass::OutputRelative, scale}};
    return add_image_compute_pass(graph, pass, levels, [&](fg::PassBuilder& builder) {
        builder.serves(Effect::VolumeCaustics);
        builder.uniform_buffer("FrameConstants", graph.blackboard().get(keys::kFrameConstants));
        builder.read_storage("Radiance", radiance);
        builder.sample("view_depth", view_depth, fg::Filter::Nearest);
        return "godrays/godray_resolve.comp";
    });
}

}  // namespace vkw::passes
