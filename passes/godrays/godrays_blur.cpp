// add_godray_blur_pass (godrays_blur.hpp).
#include "passes/godrays/godrays_blur.hpp"

#include "engine/scene/effects.hpp"
#include "passes/common/image_compute_pass.hpp"

#include <shader_structs/godrays/godray_blur.comp.hpp>

namespace vkw::passes {

fg::ImageHandle add_godray_blur_pass(fg::FrameGraph& graph, fg::ImageHandle image, fg::ImageHandle view_depth,
                                     float scale, BlurAxis axis) {
    const bool along_x = axis == BlurAxis::X;
    const ImageComputePass pass{along_x ? "godray blur x" : "godray blur y",
                                along_x ? "godray blurred x" : "godray blurred",
                                {VK_FORMAT_R32G32B32A32_SFLOAT, fg::SizeClass::OutputRelative, scale}};
    const glsl::godray_blur_comp::Push push{glm::ivec2(along_x ? 1 : 0, along_x ? 0 : 1)};
    return add_image_compute_pass(graph, pass, push, [&](fg::PassBuilder& builder) {
        builder.serves(Effect::VolumeCaustics);
        builder.sample("source", image, fg::Filter::Nearest);
        builder.sample("view_depth", view_depth, fg::Filter::Nearest);
        return "godrays/godray_blur.comp";
    });
}

}  // namespace vkw::passes
