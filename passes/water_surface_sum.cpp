// Sum of sine and Gerstner waves on the GPU (water_surface_sum.hpp). The per-wave constants
// are those of engine/water/wave_sum_surface.cpp's constructor, computed here in double
// from the same WaveComponent fields and rounded once to fp32.
#include "passes/water_surface_sum.hpp"

#include "engine/framegraph/pass_context.hpp"
#include "passes/water_surface_grid.hpp"

#include <cmath>
#include <numbers>

namespace vkw::passes {

namespace {

// Mirrors struct Wave of shaders/water/wave_sum.comp (32 bytes in std140).
struct GpuWave {
    float k_vector[2];
    float phase_at_origin;
    float amplitude;
    float displacement_scale;
    float unused[3];
};
static_assert(sizeof(GpuWave) == 32);
// vkCmdUpdateBuffer writes at most 65536 bytes: the whole table in one call.
static_assert(sizeof(GpuWave) * kMaxGpuWaves <= 65536);

struct SumPush {
    WaterGridPush grid;
    uint32_t wave_count;
};

double radians(double degrees) { return degrees * (std::numbers::pi / 180.0); }

// k d, -w t + p, A and s / k^2 as WaveSumSurface computes them. The phase is reduced to
// [-pi, pi] in double (sin and cos do not notice), so that fp32 holds it to 2^-24 rad however
// large w t has grown, instead of to ulp(w t).
GpuWave gpu_wave(const WaveComponent& c, double time) {
    const double k = 2.0 * std::numbers::pi / c.wavelength;
    const double omega = c.speed < 0.0 ? std::sqrt(kGravity * k) : c.speed * k;
    const double a = radians(c.direction_deg);
    const double phase = std::remainder(radians(c.phase_deg) - omega * time, 2.0 * std::numbers::pi);
    GpuWave w{};
    w.k_vector[0] = static_cast<float>(k * std::cos(a));
    w.k_vector[1] = static_cast<float>(k * std::sin(a));
    w.phase_at_origin = static_cast<float>(phase);
    w.amplitude = static_cast<float>(c.amplitude);
    w.displacement_scale = static_cast<float>(c.steepness / (k * k));
    return w;
}

}  // namespace

fg::BufferHandle add_wave_sum_passes(fg::FrameGraph& graph, const WaterSurfaceInputs& inputs,
                                     const std::vector<WaveComponent>& waves) {
    // The kernel's uniform block declares all kMaxGpuWaves entries, so the buffer holds them
    // all (2 KiB); wave_count says how many are used.
    std::vector<GpuWave> table(kMaxGpuWaves, GpuWave{});
    for (size_t i = 0; i < waves.size(); ++i) table[i] = gpu_wave(waves[i], inputs.time);

    struct UploadData {
        fg::BufferHandle waves;
    };
    const auto& upload = graph.add_pass<UploadData>(
        "upload water waves", fg::PassKind::Transfer,
        [&](fg::PassBuilder& builder, UploadData& d) {
            d.waves = builder.create_buffer("water waves", {table.size() * sizeof(GpuWave)});
            d.waves = builder.copy_destination(d.waves);
        },
        [table](const UploadData& d, fg::PassContext& context) {
            vkCmdUpdateBuffer(context.cmd(), context.buffer(d.waves), 0, table.size() * sizeof(GpuWave), table.data());
        });

    struct SumData {
        fg::BufferHandle waves;
        fg::BufferHandle vertices;
    };
    const SumPush push{water_grid_push(inputs), static_cast<uint32_t>(waves.size())};
    const auto& sum = graph.add_pass<SumData>(
        "water surface (wave sum)", fg::PassKind::Compute,
        [&](fg::PassBuilder& builder, SumData& d) {
            d.waves = builder.uniform_buffer(upload.waves, VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT);
            d.vertices = create_water_vertices(builder, inputs.grid_resolution);
        },
        [push](const SumData& d, fg::PassContext& context) {
            ComputePipelineDesc desc;
            desc.shader = "water/wave_sum.comp";
            desc.layout.bindings = {{0, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, 1, VK_SHADER_STAGE_COMPUTE_BIT},
                                    {1, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, 1, VK_SHADER_STAGE_COMPUTE_BIT}};
            desc.layout.push_constant_bytes = sizeof(SumPush);
            const Pipeline& pipeline = context.pipeline("wave sum", desc);
            dispatch_water_grid(context, pipeline, context.uniform_buffer(0, d.waves), d.vertices, push);
        });
    return sum.vertices;
}

}  // namespace vkw::passes
