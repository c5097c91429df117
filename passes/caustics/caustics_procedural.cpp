// add_caustic_procedural_pass (caustics_procedural.hpp).
#include "passes/caustics/caustics_procedural.hpp"

#include "passes/caustics/caustics_map_frame.hpp"
#include "passes/common/image_compute_pass.hpp"

#include <shader_structs/caustics/caustic_procedural.comp.hpp>

#include <cmath>

namespace vkw::passes {
namespace {

// The push-constant block of shaders/caustics/caustic_procedural.comp, generated from its SPIR-V (tools/shader_structs).
using ProceduralPush = glsl::caustic_procedural_comp::Push;

}  // namespace

CausticMap add_caustic_procedural_pass(fg::FrameGraph& graph, const CausticInputs& inputs) {
    const CausticMapFrame frame = fit_caustic_map(inputs);
    ProceduralPush push{};
    for (int c = 0; c < 3; ++c)
        push.e_floor[c] = frame.sun_up ? float(frame.flat_texel_flux[c] / frame.texel_area) : 0.0f;
    push.sun[0] = float(frame.s.x), push.sun[1] = float(frame.s.y), push.sun[2] = float(frame.s.z);
    push.sun[3] = float(inputs.ior);
    push.t[0] = float(frame.direction.x), push.t[1] = float(frame.direction.y), push.t[2] = float(frame.direction.z);
    push.t[3] = float(inputs.water_level);
    push.corner[0] = float(frame.corner.x), push.corner[1] = float(frame.corner.y);
    push.texel[0] = float(frame.texel.x), push.texel[1] = float(frame.texel.y);
    push.half_extent = float(inputs.half_extent);
    push.resolution = inputs.grid_resolution;
    push.width = frame.width;
    push.height = frame.height;
    const fg::BufferHandle frame_buffer = add_caustic_map_frame_pass(graph, inputs);

    const ImageComputePass pass{"caustic procedural", "caustic irradiance", caustic_map_image(frame), "irradiance"};
    const fg::ImageHandle irradiance = add_image_compute_pass(graph, pass, push, [&](fg::PassBuilder& builder) {
        builder.read_storage("Surface", inputs.surface);
        return "caustics/caustic_procedural.comp";
    });
    return {irradiance, frame_buffer};
}

}  // namespace vkw::passes
