// add_caustic_procedural_pass (caustics_procedural.hpp).
#include "passes/caustics/caustics_procedural.hpp"

#include "engine/framegraph/pass_context.hpp"
#include "passes/caustics/caustics_map_frame.hpp"

#include <cmath>

namespace vkw::passes {
namespace {

constexpr uint32_t kGroupSide = 8;  // local_size of caustic_procedural.comp

// Mirrors the push constants of shaders/caustics/caustic_procedural.comp.
struct ProceduralPush {
    float e_floor[4];     // rgb: E_perp under flat water at the floor (T, cos ratio, extinction), W m^-2
    float sun[4];         // xyz: the direction the sunlight travels; w: n
    float t[4];           // xyz: the flat-water refracted sun; w: the water's mean level
    float corner[2];      // (x, z) at the mean level of texel coordinate (0, 0), m
    float texel[2];       // texel size along x and z, m
    float half_extent;    // E: the surface grid spans [-E, E]^2
    uint32_t resolution;  // R cells per side
    uint32_t width, height;
};

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

    struct Data {
        fg::BufferHandle surface;
        fg::ImageHandle irradiance;
    };
    const auto& data = graph.add_pass<Data>(
        "caustic procedural", fg::PassKind::Compute,
        [&](fg::PassBuilder& builder, Data& d) {
            const VkPipelineStageFlags2 stage = VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT;
            d.surface = builder.read_storage(inputs.surface, stage);
            d.irradiance =
                builder.write_storage(builder.create_image("caustic irradiance", caustic_map_image(frame)), stage);
        },
        [push](const Data& d, fg::PassContext& context) {
            ComputePipelineDesc desc;
            desc.shader = "caustics/caustic_procedural.comp";
            const Pipeline& pipeline = context.pipeline("caustic procedural", desc);
            context.bind(pipeline, {context.storage_buffer(0, d.surface), context.storage_image(1, d.irradiance)});
            context.push_constants(pipeline, push);
            vkCmdDispatch(context.cmd(), (push.width + kGroupSide - 1) / kGroupSide,
                          (push.height + kGroupSide - 1) / kGroupSide, 1);
        });
    return {data.irradiance, frame_buffer};
}

}  // namespace vkw::passes
