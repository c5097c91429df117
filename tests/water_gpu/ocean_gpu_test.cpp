// The GPU FFT ocean (passes/water/water_surface_ocean.cpp) against the CPU ocean of engine/water:
// the GPU evolves the CPU's h0 (uploaded once in fp32), so at vertices on FFT nodes it must
// reproduce evaluate_ocean_grid to fp32 FFT error, and between nodes the CPU grid's fields
// interpolated bilinearly (the GPU's sampling) to that plus the interpolation's rounding.
#include "engine/framegraph/executor.hpp"
#include "engine/vk/resources.hpp"
#include "engine/water/fft_ocean.hpp"
#include "engine/water/ocean_grid.hpp"
#include "passes/present/readback.hpp"
#include "passes/water/water_surface.hpp"
#include "passes/water/water_surface_ocean.hpp"
#include "passes/water/water_surface_spectrum.hpp"
#include "tests/support/gpu_test.hpp"
#include "tests/water_gpu/fp32_error.hpp"
#include "tests/water_gpu/ocean_reference.hpp"
#include "tests/water_gpu/water_gpu_support.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <memory>
#include <string>
#include <vector>

namespace vkw::test {
namespace {

constexpr uint64_t kSeed = 20240917;

struct OceanCase {
    FftOceanSettings ocean;
    double half_extent;
    uint32_t grid_resolution;
    double time;
};

passes::WaterSurfaceInputs ocean_inputs(const OceanCase& c, const passes::OceanSpectrumBuffer& buffer) {
    passes::WaterSurfaceInputs inputs;
    inputs.level = -0.4;
    inputs.half_extent = c.half_extent;
    inputs.grid_resolution = c.grid_resolution;
    inputs.time = c.time;
    inputs.waves.model = WaveModel::FftOcean;
    inputs.waves.ocean = c.ocean;
    inputs.waves.seed = kSeed;
    inputs.ocean = &buffer;
    return inputs;
}

FftOceanSettings ocean_settings(uint32_t n, double patch_size, OceanSpectrum kind, double choppiness) {
    FftOceanSettings ocean;
    ocean.resolution = n;
    ocean.patch_size = patch_size;
    ocean.wind_speed = 7.0;
    ocean.wind_direction_deg = 25.0;
    ocean.spectrum = kind;
    ocean.fetch = 20000.0;
    ocean.choppiness = choppiness;
    return ocean;
}

// Every vertex against the CPU; with `on_nodes` the case must put every vertex on a node,
// without it fewer than a tenth.
void expect_matches_cpu(Context& context, const OceanCase& c, bool on_nodes) {
    const auto spectrum = std::make_shared<const FftOceanSpectrum>(make_ocean_spectrum(c.ocean, kSeed));
    const passes::OceanSpectrumBuffer buffer(context, spectrum);
    const passes::WaterSurfaceInputs inputs = ocean_inputs(c, buffer);
    const std::vector<GpuVertex> gpu = read_water_surface(context, inputs);
    const OceanReference reference = ocean_reference(*spectrum, c.ocean.choppiness, c.time);
    const uint32_t row = inputs.grid_resolution + 1;
    WorstRatio worst;
    uint32_t vertices_on_nodes = 0;
    for (uint32_t j = 0; j < row; ++j) {
        for (uint32_t i = 0; i < row; ++i) {
            const double x0 = vertex_parameter(i, inputs), z0 = vertex_parameter(j, inputs);
            const double ux = x0 / reference.grid.spacing(), uz = z0 / reference.grid.spacing();
            vertices_on_nodes += ux == std::floor(ux) && uz == std::floor(uz);
            const auto [cpu, tolerance] = ocean_sample(reference, x0, z0, inputs.level);
            expect_vertex_near(gpu[j * row + i], cpu, tolerance,
                               "vertex " + std::to_string(i) + "," + std::to_string(j), worst);
        }
    }
    if (on_nodes) {
        EXPECT_EQ(vertices_on_nodes, row * row);
    } else {
        EXPECT_LT(vertices_on_nodes, row * row / 10);
    }
    std::printf("max |h| %.3f m; ", reference.grid.max_abs_height());
    worst.print();
}

using water_gpu_ocean = GpuTest;

TEST_F(water_gpu_ocean, HeightfieldEqualsTheCpuFftGridAtItsNodes) {
    // Node spacing 64 / 32 = 2 m, vertex spacing 2 E / R = 2 m, -E = -32 m on a node: the
    // vertices are the FFT nodes, and the patch repeats once across the grid.
    expect_matches_cpu(context(), {ocean_settings(32, 64.0, OceanSpectrum::Phillips, 0.0), 32.0, 32, 2.5}, true);
}

TEST_F(water_gpu_ocean, ChoppyJonswapEqualsTheCpuFftGridAtItsNodes) {
    expect_matches_cpu(context(), {ocean_settings(64, 32.0, OceanSpectrum::Jonswap, 0.8), 16.0, 64, 13.0}, true);
}

TEST_F(water_gpu_ocean, ChoppyOceanBetweenNodesIsTheBilinearCpuGrid) {
    // Vertex spacing 1 m, node spacing 50 / 32 = 1.5625 m: most vertices fall between nodes.
    expect_matches_cpu(context(), {ocean_settings(32, 50.0, OceanSpectrum::Phillips, 0.6), 20.0, 40, 7.0}, false);
}

// The bound the GPU writes after the fields (shaders/water/ocean_height_bound.comp) is the largest
// |h| over the CPU's double-precision grid at its nodes, to the fp32 FFT's error bound for the height
// (ocean_reference.hpp): the per-pixel march's slab and the camera medium's band rest on it.
TEST_F(water_gpu_ocean, HeightBoundIsTheGridsLargestHeight) {
    const OceanCase c{ocean_settings(64, 32.0, OceanSpectrum::Jonswap, 0.8), 16.0, 64, 13.0};
    const auto spectrum = std::make_shared<const FftOceanSpectrum>(make_ocean_spectrum(c.ocean, kSeed));
    const passes::OceanSpectrumBuffer buffer(context(), spectrum);
    const passes::WaterSurfaceInputs inputs = ocean_inputs(c, buffer);
    const uint32_t n = c.ocean.resolution;
    const VkDeviceSize bytes = (VkDeviceSize{passes::kOceanGridCount} * n * n + 1) * 4 * sizeof(float);
    Buffer readback(context(), {bytes, VK_BUFFER_USAGE_TRANSFER_DST_BIT, true}, "ocean fields readback");
    {
        fg::PipelineStore pipelines;
        fg::FrameGraph graph;
        const passes::WaterSurfaceBuffers surface =
            passes::add_water_surface_passes(graph, inputs, c.grid_resolution, passes::ScreenMesh{});
        ASSERT_TRUE(surface.ocean_fields.has_value());
        passes::add_readback_pass(graph, *surface.ocean_fields, readback.handle(), bytes);
        graph.compile(1, 1);
        fg::FrameExecutor executor(context(), graph, pipelines, {.check_finite = true, .timing = fg::TimingMode::None});
        executor.execute();
    }
    std::vector<float> fields(bytes / sizeof(float));
    std::memcpy(fields.data(), readback.mapped(), bytes);
    const float gpu_bound = fields[fields.size() - 4];
    const OceanReference reference = ocean_reference(*spectrum, c.ocean.choppiness, c.time);
    const double cpu_largest = reference.grid.max_abs_height();
    std::printf("largest |h|: GPU %.6f m, CPU %.6f m (the all-time bound 2 sum |h0|: %.3f m)\n", gpu_bound, cpu_largest,
                spectrum->amplitude_bound());
    EXPECT_NEAR(gpu_bound, cpu_largest, reference.node_error[kOceanHeight]);
    // Not the all-time bound: a third of it or less here, which is what shortens the march.
    EXPECT_LT(3.0 * cpu_largest, spectrum->amplitude_bound());
}

TEST_F(water_gpu_ocean, SameTimeAndSeedGiveBitIdenticalVertices) {
    const OceanCase c{ocean_settings(32, 50.0, OceanSpectrum::Phillips, 0.6), 20.0, 40, 7.0};
    const auto spectrum = std::make_shared<const FftOceanSpectrum>(make_ocean_spectrum(c.ocean, kSeed));
    const passes::OceanSpectrumBuffer buffer(context(), spectrum);
    const std::vector<GpuVertex> first = read_water_surface(context(), ocean_inputs(c, buffer));
    const std::vector<GpuVertex> second = read_water_surface(context(), ocean_inputs(c, buffer));
    ASSERT_EQ(first.size(), second.size());
    EXPECT_EQ(std::memcmp(first.data(), second.data(), first.size() * sizeof(GpuVertex)), 0);
}

}  // namespace
}  // namespace vkw::test
