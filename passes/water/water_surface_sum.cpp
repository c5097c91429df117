// Sum of sine and Gerstner waves on the GPU (water_surface_sum.hpp). The per-wave constants
// are engine/water/wave_terms.hpp's, the CPU surface's own, computed in double and rounded
// once to fp32.
#include "passes/water/water_surface_sum.hpp"

#include "engine/framegraph/pass_context.hpp"
#include "engine/water/wave_terms.hpp"
#include "passes/water/water_surface_grid.hpp"

#include <shader_structs/water/wave_sum.comp.hpp>

#include <algorithm>
#include <cmath>
#include <numbers>

namespace vkw::passes {

namespace {

// struct Wave of shaders/water/wave_sum.comp (32 bytes in std140) and its push block (a
// WaterGridPush, then the number of waves), generated from its SPIR-V.
using GpuWave = glsl::wave_sum_comp::Wave;
using SumPush = glsl::wave_sum_comp::Params;
// The kernel's uniform block holds kMaxGpuWaves of them; vkCmdUpdateBuffer writes at most 65536
// bytes: the whole table in one call.
static_assert(sizeof(glsl::wave_sum_comp::Waves) == sizeof(GpuWave) * kMaxGpuWaves);
static_assert(sizeof(GpuWave) * kMaxGpuWaves <= 65536);

// wave_terms() rounded to fp32. The phase is reduced to [-pi, pi] in double first (sin and cos
// do not notice), so that fp32 holds it to 2^-24 rad however large w t has grown, instead of to
// ulp(w t).
GpuWave gpu_wave(const WaveComponent& c, double time) {
    const WaveTerms terms = wave_terms(c, time);
    GpuWave w{};
    w.k_vector[0] = static_cast<float>(terms.k_vector.x);
    w.k_vector[1] = static_cast<float>(terms.k_vector.y);
    w.phase_at_origin = static_cast<float>(std::remainder(terms.phase_at_origin, 2.0 * std::numbers::pi));
    w.amplitude = static_cast<float>(terms.amplitude);
    w.displacement_scale = static_cast<float>(terms.displacement_scale);
    return w;
}

}  // namespace

fg::BufferHandle add_wave_table_pass(fg::FrameGraph& graph, const std::vector<WaveComponent>& waves, double time) {
    // The kernel's uniform block declares all kMaxGpuWaves entries, so the buffer holds them
    // all (2 KiB); wave_count says how many are used, and no shader reads past it. Only those
    // are uploaded (one zero entry for none: an update writes at least 4 bytes): the frame
    // declares this pass every frame, and a 2 KiB table, copied into the pass, was the dearest
    // part of declaring the water's passes.
    std::vector<GpuWave> table(std::max<size_t>(waves.size(), 1), GpuWave{});
    for (size_t i = 0; i < waves.size(); ++i) table[i] = gpu_wave(waves[i], time);
    struct UploadData {
        fg::BufferHandle waves;
    };
    const auto& upload = graph.add_pass<UploadData>(
        "upload water waves", fg::PassKind::Transfer,
        [&](fg::PassBuilder& builder, UploadData& d) {
            d.waves = builder.create_buffer("water waves", {kMaxGpuWaves * sizeof(GpuWave)});
            d.waves = builder.copy_destination(d.waves);
        },
        [table = std::move(table)](const UploadData& d, fg::PassContext& context) {
            vkCmdUpdateBuffer(context.cmd(), context.buffer(d.waves), 0, table.size() * sizeof(GpuWave), table.data());
        });
    return upload.waves;
}

WaterSurfaceBuffers add_wave_sum_passes(fg::FrameGraph& graph, const WaterSurfaceInputs& inputs,
                                        const std::vector<WaveComponent>& waves, uint32_t mesh_resolution) {
    WaterSurfaceBuffers out;
    out.waves = add_wave_table_pass(graph, waves, inputs.time);
    const SumPush push{water_grid_push(inputs), static_cast<uint32_t>(waves.size())};
    add_water_grid_and_mesh_passes(graph,
                                   {"water surface (wave sum)", "water/wave_sum.comp", "wave sum", "Waves", true},
                                   "water mesh (wave sum)", out.waves, push, mesh_resolution, out);
    out.model.wave_count = push.wave_count;
    // sum (A k + s) k bounds |d^2 P / du^2| of the waves.
    double curvature = 0.0, shortest = 0.0, slope = 0.0, steepness = 0.0;
    for (const WaveComponent& w : waves) {
        shortest = shortest > 0.0 ? std::min(shortest, w.wavelength) : w.wavelength;
        const double k = 2.0 * std::numbers::pi / w.wavelength;
        curvature += (w.amplitude * k + w.steepness) * k;
        slope += w.amplitude * k;
        steepness += w.steepness;
    }
    set_water_mesh_sag(out.model, inputs.half_extent, mesh_resolution, curvature);
    out.model.march_step = static_cast<float>(shortest / 8.0);
    // |grad h| <= sum A k over the parameter; the horizontal map's Jacobian is at least
    // 1 - sum steepness, which stretches it over world (x, z) by at most its inverse.
    if (steepness < 0.95) out.model.slope_bound = static_cast<float>(slope / (1.0 - steepness));
    return out;
}

}  // namespace vkw::passes
