// add_caustic_blur_pass (caustics_blur.hpp).
#include "passes/caustics/caustics_blur.hpp"

#include "engine/scene/effects.hpp"
#include "passes/caustics/caustics_map_frame.hpp"
#include "passes/common/image_compute_pass.hpp"

#include <shader_structs/caustics/caustic_blur.comp.hpp>

namespace vkw::passes {
namespace {

// The push-constant block of shaders/caustics/caustic_blur.comp, generated from its SPIR-V (tools/shader_structs).
using BlurPush = glsl::caustic_blur_comp::Push;

}  // namespace

CausticMap add_caustic_blur_pass(fg::FrameGraph& graph, const CausticMap& map, const CausticInputs& inputs,
                                 double radius) {
    const CausticMapFrame frame = fit_caustic_map(inputs);
    double flat_sum = 0.0;
    for (int c = 0; c < 3; ++c) flat_sum += frame.flat_texel_flux[c] / frame.texel_area;
    // A sun whose flat-water light is 0 (night, or a black sun) leaves nothing to blur; any
    // positive unit keeps the shader's arithmetic finite.
    if (!(flat_sum > 0.0)) flat_sum = 1.0;
    const fg::ImageInfo info = caustic_map_image(frame);

    fg::ImageHandle image = map.irradiance;
    for (const bool first : {true, false}) {
        const BlurPush push{{int32_t(frame.width), int32_t(frame.height)},
                            {first ? 1 : 0, first ? 0 : 1},
                            float(radius),
                            float(flat_sum),
                            first ? 1u : 0u,
                            0.0f};
        const std::string name = first ? "caustic blur x" : "caustic blur y";
        image = add_image_compute_pass(graph, {name, name + " target", info}, push, [&](fg::PassBuilder& builder) {
            builder.serves(Effect::CausticBlur);
            builder.read_storage("source", image);
            return "caustics/caustic_blur.comp";
        });
    }
    return {image, map.frame};
}

}  // namespace vkw::passes
