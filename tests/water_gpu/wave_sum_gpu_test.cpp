// The GPU wave sum (shaders/water/wave_sum.comp) against engine/water's WaveSumSurface in
// double precision at every vertex: sines, Gerstner waves, flat water, run-to-run identity,
// and a grid large enough to need two storage-buffer bands.
#include "engine/water/wave_sum_surface.hpp"
#include "passes/water/water_surface_grid.hpp"
#include "tests/support/gpu_test.hpp"
#include "tests/water_gpu/fp32_error.hpp"
#include "tests/water_gpu/water_gpu_support.hpp"
#include "tests/water_gpu/wave_sum_tolerance.hpp"

#include <cmath>
#include <cstdio>
#include <cstring>
#include <numbers>
#include <string>
#include <vector>

namespace vkw::test {
namespace {

passes::WaterSurfaceInputs sum_inputs(std::vector<WaveComponent> components, double time) {
    passes::WaterSurfaceInputs inputs;
    inputs.level = 0.7;
    inputs.half_extent = 12.0;
    inputs.grid_resolution = 48;
    inputs.time = time;
    inputs.waves.model = WaveModel::Sum;
    inputs.waves.components = std::move(components);
    return inputs;
}

// Every vertex of the GPU surface against WaveSumSurface::at_parameter.
void expect_matches_cpu(Context& context, const passes::WaterSurfaceInputs& inputs) {
    const std::vector<GpuVertex> gpu = read_water_surface(context, inputs);
    const WaveSumSurface surface(inputs.waves, inputs.level, inputs.time);
    const uint32_t row = inputs.grid_resolution + 1;
    WorstRatio worst;
    for (uint32_t j = 0; j < row; ++j) {
        for (uint32_t i = 0; i < row; ++i) {
            const double x0 = vertex_parameter(i, inputs), z0 = vertex_parameter(j, inputs);
            const SurfacePoint cpu = surface.at_parameter(x0, z0);
            const VertexTolerance tolerance = wave_sum_tolerance(inputs.waves.components, inputs.level, x0, z0, cpu);
            expect_vertex_near(gpu[j * row + i], cpu, tolerance,
                               "vertex " + std::to_string(i) + "," + std::to_string(j), worst);
        }
    }
    worst.print();
}

using water_gpu_wave_sum = GpuTest;

TEST_F(water_gpu_wave_sum, SinesMatchTheCpuAtEveryVertex) {
    expect_matches_cpu(context(), sum_inputs({{0.30, 7.0, 20.0, 10.0, 0.0, -1.0},
                                              {0.12, 3.1, 135.0, 80.0, 0.0, 1.5},
                                              {0.05, 1.3, -70.0, 0.0, 0.0, -1.0}},
                                             3.3));
}

TEST_F(water_gpu_wave_sum, GerstnerWavesMatchTheCpuAtEveryVertex) {
    // Steepness sum 0.8: no folding; |cross(dv, du)| stays >= 0.2 so normals are well defined.
    expect_matches_cpu(context(), sum_inputs({{0.40, 9.0, 30.0, 0.0, 0.35, -1.0},
                                              {0.15, 4.2, 160.0, 45.0, 0.25, -1.0},
                                              {0.06, 2.0, 275.0, 200.0, 0.15, 2.0},
                                              {0.02, 0.9, 95.0, 10.0, 0.05, -1.0}},
                                             41.7));
}

// No waves: (x0, level, z0) and +y exactly, the parameter computed in fp32 as the kernel does.
void expect_flat_grid(const std::vector<GpuVertex>& gpu, const passes::WaterSurfaceInputs& inputs) {
    const uint32_t row = inputs.grid_resolution + 1;
    const float e = static_cast<float>(inputs.half_extent), r = static_cast<float>(inputs.grid_resolution);
    ASSERT_EQ(gpu.size(), size_t(row) * row);
    size_t wrong = 0;
    for (uint32_t j = 0; j < row; ++j) {
        for (uint32_t i = 0; i < row; ++i) {
            const GpuVertex& v = gpu[size_t(j) * row + i];
            const float expected[8] = {e * (2.0f * float(i) - r) / r,
                                       static_cast<float>(inputs.level),
                                       e * (2.0f * float(j) - r) / r,
                                       1.0f,
                                       0.0f,
                                       1.0f,
                                       0.0f,
                                       0.0f};
            if (std::memcmp(&v, expected, sizeof expected) != 0 && wrong++ < 5) {
                ADD_FAILURE() << "vertex " << i << "," << j << ": " << v.position[0] << " " << v.position[1] << " "
                              << v.position[2] << ", expected " << expected[0] << " " << expected[1] << " "
                              << expected[2];
            }
        }
    }
    EXPECT_EQ(wrong, 0u);
}

TEST_F(water_gpu_wave_sum, FlatWaterIsTheExactGridAtTheLevel) {
    passes::WaterSurfaceInputs inputs = sum_inputs({}, 5.0);
    inputs.waves.model = WaveModel::Flat;
    expect_flat_grid(read_water_surface(context(), inputs), inputs);
}

TEST_F(water_gpu_wave_sum, GridOverOneBindingIsWrittenInBands) {
    // (2049)^2 vertices of 32 bytes exceed lavapipe's 128 MiB maxStorageBufferRange: two
    // bands, the second starting at a row > 0. Every vertex must still land in its slot.
    passes::WaterSurfaceInputs inputs = sum_inputs({}, 0.0);
    inputs.waves.model = WaveModel::Flat;
    inputs.grid_resolution = 2048;
    const VkPhysicalDeviceLimits& limits = context().properties().limits;
    const size_t bands = passes::water_grid_bands(limits.maxStorageBufferRange, limits.minStorageBufferOffsetAlignment,
                                                  inputs.grid_resolution)
                             .size();
    std::printf("R = 2048 takes %zu band(s) on this device\n", bands);
    expect_flat_grid(read_water_surface(context(), inputs), inputs);
}

TEST_F(water_gpu_wave_sum, SameInputsGiveBitIdenticalVertices) {
    const passes::WaterSurfaceInputs inputs =
        sum_inputs({{0.40, 9.0, 30.0, 0.0, 0.35, -1.0}, {0.15, 4.2, 160.0, 45.0, 0.25, -1.0}}, 17.25);
    const std::vector<GpuVertex> first = read_water_surface(context(), inputs);
    const std::vector<GpuVertex> second = read_water_surface(context(), inputs);
    ASSERT_EQ(first.size(), second.size());
    EXPECT_EQ(std::memcmp(first.data(), second.data(), first.size() * sizeof(GpuVertex)), 0);
}

}  // namespace
}  // namespace vkw::test
