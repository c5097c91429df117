// add_godray_blur (godrays_blur.hpp).
#include "passes/godrays/godrays_blur.hpp"

#include "engine/scene/effects.hpp"
#include "passes/common/image_compute_pass.hpp"

#include <shader_structs/godrays/godray_blur.comp.hpp>

namespace vkw::passes {

fg::ImageHandle add_godray_blur(fg::FrameGraph& graph, fg::ImageHandle image, fg::ImageHandle view_depth, float scale) {
    const auto blur = [&](fg::ImageHandle source, const char* pass, const char* blurred, glm::ivec2 axis) {
        return add_image_compute_pass(graph, {pass, blurred, {.scale = scale}}, glsl::godray_blur_comp::Push{axis},
                                      [&](fg::PassBuilder& builder) {
                                          builder.serves(Effect::VolumeCaustics);
                                          builder.sample("source", source, fg::Filter::Nearest);
                                          builder.sample("view_depth", view_depth, fg::Filter::Nearest);
                                          return "godrays/godray_blur.comp";
                                      });
    };
    return blur(blur(image, "godray blur x", "godray blurred x", {1, 0}), "godray blur y", "godray blurred", {0, 1});
}

}  // namespace vkw::passes
