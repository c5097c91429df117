// Wind-wave variance spectra for the FFT ocean, as densities over the wave-vector plane:
// Psi(k) in m^4, so that the integral of Psi over all k (in (rad/m)^2) is the variance of the
// height, <h^2> in m^2. Both share one directional spreading, D(theta) = cos^2(theta) / pi
// with theta the angle between k and the wind (normalised: its integral over 2 pi is 1).
// It is Tessendorf's |k^ . w^|^2: waves run along and against the wind alike.
//
// Phillips (Tessendorf 2001, "Simulating Ocean Water", with the continuous
// normalisation made explicit): the omnidirectional saturation range S(k) = (alpha / 2) k^-3,
// alpha = 0.0081 (Phillips' constant; the deep-water equivalent of alpha g^2 w^-5), with the
// large-wave cut-off exp(-1 / (k L)^2), L = V^2 / g, and the small-wave suppression
// exp(-k^2 l^2), l = L / 1000:
//   Psi(k) = alpha / (2 pi) exp(-1 / (k L)^2) / k^4 cos^2(theta) exp(-k^2 l^2).
// Without the suppression its integral is alpha L^2 / 4 (phillips_variance), so the
// significant wave height 4 sqrt(<h^2>) is 2 sqrt(alpha) V^2 / g = 0.18 V^2 / g.
//
// JONSWAP (Hasselmann et al. 1973, "Measurements of wind-wave growth and swell decay
// during the Joint North Sea Wave Project", Dtsch. Hydrogr. Z. A8(12); the fetch laws as
// collected by Horvath 2015, "Empirical directional wave spectra for computer graphics"):
//   S(w) = alpha g^2 / w^5 exp(-5/4 (w_p / w)^4) gamma^r,
//   r = exp(-(w - w_p)^2 / (2 sigma^2 w_p^2)), gamma = 3.3, sigma = 0.07 (w <= w_p) or 0.09,
//   alpha = 0.076 (V^2 / (F g))^0.22, w_p = 22 (g^2 / (V F))^(1/3), F the fetch,
// carried to wave numbers with w = sqrt(g k): Psi(k) = S(w) (dw/dk) D(theta) / k,
// dw/dk = g / (2 w).
//
// ocean_spectrum multiplies the chosen density by amplitude_scale^2 (heights scale by
// amplitude_scale). Psi(0) = 0.
#pragma once

#include <glm/glm.hpp>

#include "engine/water/wave_params.hpp"

namespace vkw {

inline constexpr double kPhillipsAlpha = 0.0081;
inline constexpr double kJonswapGamma = 3.3;
inline constexpr double kJonswapSigmaBelowPeak = 0.07;
inline constexpr double kJonswapSigmaAbovePeak = 0.09;

double directional_spreading(const glm::dvec2& k, double wind_direction_deg);
double phillips_spectrum(const glm::dvec2& k, const FftOceanSettings& ocean);

struct JonswapParameters {
    double alpha;       // 0.076 (V^2 / (F g))^0.22
    double omega_peak;  // 22 (g^2 / (V F))^(1/3), rad/s
};
JonswapParameters jonswap_parameters(const FftOceanSettings& ocean);
// S(w) in m^2 s (its integral over w > 0 is <h^2>); 0 at w = 0.
double jonswap_frequency_spectrum(double omega, const FftOceanSettings& ocean);
double jonswap_spectrum(const glm::dvec2& k, const FftOceanSettings& ocean);
double ocean_spectrum(const glm::dvec2& k, const FftOceanSettings& ocean);

// alpha L^2 / 4 amplitude_scale^2: the integral of the Phillips density without the
// small-wave suppression, which removes a relative 2 ln(1000) (l / L)^2 = 1.4e-5 of it
// (to leading order in l / L).
double phillips_variance(const FftOceanSettings& ocean);

}  // namespace vkw
