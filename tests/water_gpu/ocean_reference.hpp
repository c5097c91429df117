// The CPU's FFT ocean as the GPU samples it (the fields of evaluate_ocean_grid interpolated
// bilinearly, as shaders/water/ocean_point.glsl does) and the GPU's fp32 error bounds, shared
// by the grid kernel's tests and the per-pixel refinement's.
#pragma once

#include "engine/water/fft_ocean.hpp"
#include "engine/water/ocean_grid.hpp"
#include "tests/water_gpu/fp32_error.hpp"
#include "tests/water_gpu/water_gpu_support.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <utility>

namespace vkw::test {

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
inline OceanReference ocean_reference(const FftOceanSpectrum& spectrum, double choppiness, double time) {
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
inline std::pair<SurfacePoint, VertexTolerance> ocean_sample(const OceanReference& reference, double x0, double z0,
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

}  // namespace vkw::test
