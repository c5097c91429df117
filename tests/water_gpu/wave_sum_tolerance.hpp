// The fp32 error bound of the GPU wave sum (shaders/water/wave_sum_point.glsl) at one grid
// parameter, shared by the grid kernel's tests and the per-pixel refinement's.
#pragma once

#include "engine/water/surface.hpp"
#include "engine/water/wave_params.hpp"
#include "tests/water_gpu/fp32_error.hpp"
#include "tests/water_gpu/water_gpu_support.hpp"

#include <cmath>
#include <numbers>
#include <vector>

namespace vkw::test {

// The fp32 error of the kernel at parameter (x0, z0), term by term (fp32_error.hpp's u):
// - the parameter E (2 i - R) / R: E rounded, one product, one quotient: 3 u |x0|, which moves
//   the point by |dP/du| 3 u |x0| (and likewise in z0), and the tangents by the second
//   derivatives, at most sum (A k^2 + s k) per unit of parameter;
// - the phase theta = k . x + phase0: k and x rounded (u each, and 3 u for x), two products,
//   the sum and the phase's own rounding: u (7 k (|x0| + |z0|) + 3 pi) rad, then sin/cos
//   (kTrigError); a wave's position terms are at most A + s / k and its tangent terms at most
//   A k + s, each also rounded by about 4 u;
// - the running sums: each of W + 1 additions rounds by u times the sums' magnitude.
inline VertexTolerance wave_sum_tolerance(const std::vector<WaveComponent>& waves, double level, double x0, double z0,
                                          const SurfacePoint& cpu) {
    const double dx = 3.0 * kUnitRoundoff * std::abs(x0), dz = 3.0 * kUnitRoundoff * std::abs(z0);
    double position_terms = 0.0, tangent_terms = 0.0, second_derivative = 0.0;
    double position_scale = std::abs(x0) + std::abs(z0) + std::abs(level), tangent_scale = 1.0;
    for (const WaveComponent& w : waves) {
        const double k = 2.0 * std::numbers::pi / w.wavelength;
        const double phase_error =
            kUnitRoundoff * (7.0 * k * (std::abs(x0) + std::abs(z0)) + 3.0 * std::numbers::pi) + kTrigError;
        const double position_size = w.amplitude + w.steepness / k, tangent_size = w.amplitude * k + w.steepness;
        position_terms += position_size * (phase_error + 4.0 * kUnitRoundoff);
        tangent_terms += tangent_size * (phase_error + 4.0 * kUnitRoundoff);
        second_derivative += tangent_size * k;
        position_scale += position_size;
        tangent_scale += tangent_size;
    }
    const double sums = double(waves.size() + 1) * kUnitRoundoff;
    const double shift = glm::length(cpu.dP_du) * dx + glm::length(cpu.dP_dv) * dz;
    const double position = position_terms + sums * position_scale + shift;
    // Each tangent's three components: the Euclidean error is at most sqrt(3) times the bound.
    const double tangent = std::sqrt(3.0) * (tangent_terms + sums * tangent_scale + second_derivative * (dx + dz));
    return {glm::dvec3(position), normal_error(cpu.dP_du, cpu.dP_dv, tangent, tangent)};
}

}  // namespace vkw::test
