// The GPU FFT ocean (passes/water/water_surface_ocean.cpp) against the CPU ocean of engine/water:
// the GPU evolves the CPU's h0 (uploaded once in fp32), so at vertices on FFT nodes it must
// reproduce evaluate_ocean_grid to fp32 FFT error, and between nodes the CPU grid's fields
// interpolated bilinearly (the GPU's sampling) to that plus the interpolation's rounding.
#include "engine/water/fft_ocean.hpp"
#include "engine/water/ocean_grid.hpp"
#include "passes/water/water_surface_spectrum.hpp"
#include "tests/support/gpu_test.hpp"
#include "tests/water_gpu/fp32_error.hpp"
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

// The CPU fields on the FFT grid and a bound on the GPU's error in each at the nodes.
struct OceanReference {
    FftOceanGrid grid;
    OceanFieldValues node_error{};
};

// Per field f, S_f = sum over modes of |m_f(k)| (|h0(k)| + |h0(-k)|) >= sum |m_f h~|. The GPU
// packs fields 2p and 2p + 1 into one complex plane, so the plane's FFT error (fp32_error.hpp)
// and its inputs' errors are shared by both and scale with S_2p + S_2p+1. Each input
// m_f h~ is rounded relatively by about u (16 + 8 w t) + 2 trig: h0 to fp32 (u), k and w
// from fp32 dk (4 u), the phase w t with its reduction (8 u w t, then sin and cos), the
// products with the rotation (4 u) and the multiplier (6 u, then 3 u).
OceanReference ocean_reference(const FftOceanSpectrum& spectrum, double choppiness, double time) {
    OceanReference reference{evaluate_ocean_grid(spectrum, choppiness, time), {}};
    OceanFieldValues sum_abs{};
    double max_omega = 0.0;
    for (uint32_t b = 0; b < spectrum.n; ++b) {
        for (uint32_t a = 0; a < spectrum.n; ++a) {
            const std::size_t i = std::size_t(b) * spectrum.n + a;
            const glm::dvec2 k = spectrum.wave_vector(a, b);
            const OceanFieldMultipliers m = ocean_field_multipliers(k, choppiness);
            const double size = std::abs(spectrum.h0[i]) + std::abs(spectrum.h0[spectrum.opposite(i)]);
            for (uint32_t f = 0; f < kOceanFieldCount; ++f) sum_abs[f] += std::abs(m[f]) * size;
            max_omega = std::max(max_omega, ocean_angular_frequency(k));
        }
    }
    const double input_error = kUnitRoundoff * (16.0 + 8.0 * max_omega * time) + 2.0 * kTrigError;
    for (uint32_t f = 0; f < kOceanFieldCount; f += 2) {
        const double plane = sum_abs[f] + sum_abs[f + 1];
        reference.node_error[f] = reference.node_error[f + 1] =
            plane * input_error + inverse_fft_error(plane, spectrum.n);
    }
    return reference;
}

// The CPU point at parameter (x0, z0), the fields interpolated bilinearly between the grid
// nodes as shaders/water/ocean_grid.comp does, and the GPU's tolerance there. On a node the
// GPU's weights are exactly 0 and 1 (the tests choose E, R, patch and n so that the fp32
// parameter and x0 n / patch are exact) and only the node errors remain; between nodes the
// weights carry the parameter's 3 u |x0| and the product's rounding, u (4 |x0 n / patch| + 2),
// times the spread of the corner values, and the three lerps round by about 6 u max |corner|.
std::pair<SurfacePoint, VertexTolerance> ocean_sample(const OceanReference& reference, double x0, double z0,
                                                      double level) {
    const FftOceanGrid& grid = reference.grid;
    const double ux = x0 / grid.spacing(), uz = z0 / grid.spacing();
    const double cx = std::floor(ux), cz = std::floor(uz);
    const double wx = ux - cx, wz = uz - cz;
    const int n = int(grid.n);
    auto wrap = [n](double c) { return uint32_t(((int64_t(c) % n) + n) % n); };
    const uint32_t x_lo = wrap(cx), x_hi = wrap(cx + 1), z_lo = wrap(cz), z_hi = wrap(cz + 1);
    const bool on_node = wx == 0.0 && wz == 0.0;
    const double weight_error = kUnitRoundoff * (4.0 * std::max(std::abs(ux), std::abs(uz)) + 2.0);
    OceanFieldValues f{}, error{};
    for (uint32_t field = 0; field < kOceanFieldCount; ++field) {
        const std::array<double, 4> c = {grid.values(x_lo, z_lo)[field], grid.values(x_hi, z_lo)[field],
                                         grid.values(x_lo, z_hi)[field], grid.values(x_hi, z_hi)[field]};
        f[field] = (c[0] * (1 - wx) + c[1] * wx) * (1 - wz) + (c[2] * (1 - wx) + c[3] * wx) * wz;
        error[field] = reference.node_error[field];
        if (!on_node) {
            const auto [lo, hi] = std::minmax_element(c.begin(), c.end());
            const double largest = std::max(std::abs(*lo), std::abs(*hi));
            error[field] += 2.0 * weight_error * (*hi - *lo) + 6.0 * kUnitRoundoff * largest;
        }
    }
    const SurfacePoint cpu = ocean_surface_point(f, x0, z0, level);
    VertexTolerance tolerance;
    tolerance.position.x = error[kOceanDispX] + kUnitRoundoff * (5.0 * std::abs(x0) + 2.0 * std::abs(f[kOceanDispX]));
    tolerance.position.y = error[kOceanHeight] + 2.0 * kUnitRoundoff * std::abs(cpu.position.y);
    tolerance.position.z = error[kOceanDispZ] + kUnitRoundoff * (5.0 * std::abs(z0) + 2.0 * std::abs(f[kOceanDispZ]));
    const double du_error =
        error[kOceanDispXdX] + error[kOceanSlopeX] + error[kOceanDispXdZ] + kUnitRoundoff * std::abs(cpu.dP_du.x);
    const double dv_error =
        error[kOceanDispXdZ] + error[kOceanSlopeZ] + error[kOceanDispZdZ] + kUnitRoundoff * std::abs(cpu.dP_dv.z);
    tolerance.normal = normal_error(cpu.dP_du, cpu.dP_dv, du_error, dv_error);
    return {cpu, tolerance};
}

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
