// The slope covariance of the wave components a pixel cannot resolve, as a table over the pixel's
// cutoff wavenumber, for the sun's glitter (docs/model.md section 1, "Sun glitter"). A pixel whose
// footprint on the surface has side w has the Nyquist wavenumber k_c = pi / w; of a component of
// wavenumber k, the share of its slope variance that varies within the footprint counts as
// unresolved: unresolved_weight(k / k_c) = 1 - sinc^2(k w / 2), about (k w)^2 / 12 for long waves
// (their slope turns within the pixel by their curvature times w) and 1 for short ones. The slopes
// of the unresolved part have the covariance
//     sum of sines and Gerstner waves:  S(k_c) = sum_i w_i A_i^2 k_i k_i^T / 2
//     FFT ocean (time-averaged):        S(k_c) = sum_k w(k) 2 |h0(k)|^2 k k^T
// (fft_ocean.hpp's normalisation: h~(k) collects h0(k) and conj(h0(-k)), whose cross terms average
// out over time). Gerstner waves count as the sines of the same height: their horizontal motion is
// left out.
#pragma once

#include <array>
#include <cstddef>

#include <glm/glm.hpp>

#include "engine/water/wave_params.hpp"

namespace vkw {

inline constexpr std::size_t kUnresolvedSlopeEntries = 16;

// Entry i holds, for the cutoff k_c(i) = exp(log_k0 + i * log_step): (S_xx, S_xz, S_zz, k_c),
// from half the smallest wavenumber to 30 times the largest; outside, the end entries stand
// (shaders/water/sun_glitter.glsl interpolates it in log k_c).
struct UnresolvedSlopeTable {
    std::array<glm::vec4, kUnresolvedSlopeEntries> entries{};
    double log_k0 = 0.0;
    double log_step = 0.0;
    double total_variance = 0.0;  // S_xx + S_zz of every component, each with weight 1
    bool any = false;             // false for flat water: no slopes at all
};

// The weight of a component of wavenumber k in the unresolved part, for cutoff k_c.
double unresolved_weight(double k_over_cutoff);

// The table for these waves. For the FFT ocean it is kept with the spectrum it was made from
// (shared_ocean_spectrum), so a frame computes it once per spectrum. Thread-safe.
UnresolvedSlopeTable unresolved_slope_table(const WaveSettings& waves);

}  // namespace vkw
