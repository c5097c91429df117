// The GPU ocean's passes (water_surface_ocean.hpp).
#include "passes/water/water_surface_ocean.hpp"

#include "engine/framegraph/pass_context.hpp"
#include "passes/water/water_surface_fft.hpp"
#include "passes/water/water_surface_grid.hpp"
#include "passes/water/water_surface_spectrum.hpp"
#include "passes/water/water_surface_sum.hpp"

#include <shader_structs/water/ocean_grid.comp.hpp>
#include <shader_structs/water/ocean_height_bound.comp.hpp>
#include <shader_structs/water/ocean_spectra.comp.hpp>

#include <numbers>

namespace vkw::passes {

namespace {

// The push-constant block of shaders/water/ocean_spectra.comp, generated from its SPIR-V (tools/shader_structs).
using SpectraPush = glsl::ocean_spectra_comp::Params;

// The push-constant block of shaders/water/ocean_grid.comp (a WaterGridPush, then the FFT's size and
// its nodes per metre).
using GridPush = glsl::ocean_grid_comp::Params;

// The push-constant block of shaders/water/ocean_height_bound.comp: the nodes per side.
using HeightBoundPush = glsl::ocean_height_bound_comp::Params;

fg::BufferHandle add_spectra_pass(fg::FrameGraph& graph, const WaterSurfaceInputs& inputs) {
    const FftOceanSpectrum& spectrum = inputs.ocean->spectrum();
    const uint32_t n = spectrum.n;
    const fg::BufferHandle h0 = inputs.ocean->import_into(graph);
    // The time in fp32: the phase w t then carries ulp(t) w, 1e-3 rad for the 11 rad/s modes of a
    // 256-mode, 64 m patch at t = 1000 s (the sum model reduces its phases in double instead; here
    // that would be a CPU pass over every mode each frame).
    const SpectraPush push{n, static_cast<float>(2.0 * std::numbers::pi / spectrum.patch_size),
                           static_cast<float>(inputs.time), static_cast<float>(inputs.waves.ocean.choppiness)};
    struct Data {
        fg::BufferHandle grids;
    };
    const auto& data = graph.add_pass<Data>(
        "ocean spectra", fg::PassKind::Compute,
        [&](fg::PassBuilder& builder, Data& d) {
            builder.read_storage("InitialSpectrum", h0);
            // The grids, then the height bound's vec4 (water_surface_ocean.hpp).
            const VkDeviceSize bytes = (VkDeviceSize{kOceanGridCount} * n * n + 1) * 4 * sizeof(float);
            d.grids = builder.write_storage("Grids", builder.create_buffer("ocean spectra", {bytes}));
        },
        [push](const Data&, fg::PassContext& context) {
            const Pipeline& pipeline =
                context.pipeline("ocean spectra", ComputePipelineDesc{"water/ocean_spectra.comp"});
            context.bind(pipeline);
            context.push_constants(pipeline, push);
            context.dispatch(pipeline, push.n, push.n);  // <= 128 groups per side
        });
    return data.grids;
}

// The largest |h| over the nodes into the vec4 after the fields: one work group.
fg::BufferHandle add_height_bound_pass(fg::FrameGraph& graph, fg::BufferHandle fields, uint32_t n) {
    struct Data {
        fg::BufferHandle grids;
    };
    const auto& data = graph.add_pass<Data>(
        "ocean height bound", fg::PassKind::Compute,
        [&](fg::PassBuilder& builder, Data& d) { d.grids = builder.read_write_storage("Grids", fields); },
        [push = HeightBoundPush{n}](const Data&, fg::PassContext& context) {
            const Pipeline& pipeline =
                context.pipeline("ocean height bound", ComputePipelineDesc{"water/ocean_height_bound.comp"});
            context.bind(pipeline);
            context.push_constants(pipeline, push);
            vkCmdDispatch(context.cmd(), 1, 1, 1);
        });
    return data.grids;
}

}  // namespace

WaterSurfaceBuffers add_ocean_passes(fg::FrameGraph& graph, const WaterSurfaceInputs& inputs,
                                     uint32_t mesh_resolution) {
    const FftOceanSpectrum& spectrum = inputs.ocean->spectrum();
    const fg::BufferHandle spectra = add_spectra_pass(graph, inputs);
    WaterSurfaceBuffers out;
    out.ocean_fields =
        add_height_bound_pass(graph, add_inverse_fft_passes(graph, spectra, spectrum.n, kOceanGridCount), spectrum.n);
    // The refinement's shader declares the sum's table too: an empty one stands in.
    out.waves = add_wave_table_pass(graph, {}, inputs.time);
    const GridPush push{water_grid_push(inputs), spectrum.n, static_cast<float>(spectrum.n / spectrum.patch_size)};
    add_water_grid_and_mesh_passes(
        graph, {"water surface (ocean grid)", "water/ocean_grid.comp", "ocean grid", "Grids", false},
        "water mesh (ocean grid)", *out.ocean_fields, push, mesh_resolution, out);
    out.model.ocean = true;
    out.model.ocean_n = push.n;
    out.model.nodes_per_metre = push.nodes_per_metre;
    out.model.march_step = 1.0f / push.nodes_per_metre;
    // As the sum's (water_surface_sum.cpp), with 4 times the spectrum's RMS second derivative: a
    // random surface has no useful bound that holds everywhere (the one that does is 100 times the
    // mesh's real sag on the built-in ocean), and where a crest exceeds this the pixel keeps the
    // mesh's point or Newton's crossing, both within the real sag.
    set_water_mesh_sag(out.model, inputs.half_extent, mesh_resolution,
                       4.0 * (1.0 + inputs.waves.ocean.choppiness) * inputs.ocean->curvature_rms());
    return out;
}

}  // namespace vkw::passes
