// Error bounds of the GPU water kernels' fp32 arithmetic, shared by the tests of the wave
// sum, the inverse FFT and the FFT ocean. Each bound is a sum of first-order terms, one per
// rounding, in units of the fp32 unit roundoff u = 2^-24 (|fl(a op b) - a op b| <= u |a op b|).
#pragma once

#include <glm/glm.hpp>

#include <cmath>
#include <numbers>

namespace vkw::test {

inline constexpr double kUnitRoundoff = 0x1.0p-24;

// Absolute error of sin and cos of an fp32 argument in [-pi, pi] (kernels reduce larger
// ones first: shaders/water/complex.glsl). Vulkan only promises 2^-11 there; lavapipe
// (llvmpipe's polynomial) stays within a few units of 2^-24, and this is what the tests
// assume: a device with hardware approximations would need a looser bound.
inline constexpr double kTrigError = 4.0 * kUnitRoundoff;

// The inverse FFT (shaders/water/ocean_fft.comp), rows then columns, 2 log2(n) radix-2
// stages. One output of a stage depends on 2^s nodes of the s-th stage before it, and those
// nodes partition the input, so their magnitudes sum to at most sum |input|; each stage adds
// at each node its twiddle's error (the angle pi * (offset / half) rounded: pi u, then cos
// and sin), the complex product's rounding (2 u per part, both parts: 2 sqrt(2) u) and the
// sum's (sqrt(2) u), relative to the node. Hence
//   |error of one output| <= 2 log2(n) (pi u + sqrt(2) trig + 3 sqrt(2) u) sum |input|.
inline double inverse_fft_error(double sum_abs_input, unsigned n) {
    const double stages = 2.0 * std::log2(double(n));
    const double per_stage =
        std::numbers::pi * kUnitRoundoff + std::sqrt(2.0) * kTrigError + 3.0 * std::sqrt(2.0) * kUnitRoundoff;
    return stages * per_stage * sum_abs_input;
}

// The error of normalize(cross(dv, du)) when the tangents carry errors of at most du_error
// and dv_error (Euclidean): the cross product's error is at most du_error |dv| + |du| dv_error
// plus its own rounding (about 4 u |du| |dv|); a perturbation e of a vector c turns its
// direction by at most 2 |e| / |c|; normalising rounds by a few u.
inline double normal_error(const glm::dvec3& du, const glm::dvec3& dv, double du_error, double dv_error) {
    const double cross = glm::length(glm::cross(dv, du));
    const double cross_error = du_error * glm::length(dv) + glm::length(du) * dv_error +
                               4.0 * kUnitRoundoff * glm::length(du) * glm::length(dv);
    return 2.0 * cross_error / cross + 4.0 * kUnitRoundoff;
}

}  // namespace vkw::test
