// Phillips and JONSWAP densities over the wave-vector plane (ocean_spectrum.hpp).
#include "engine/water/ocean_spectrum.hpp"

#include <cmath>
#include <numbers>

namespace vkw {

namespace {

constexpr double kPi = std::numbers::pi;

// L = V^2 / g: the largest wave a wind of speed V raises.
double largest_wave(const FftOceanSettings& ocean) { return ocean.wind_speed * ocean.wind_speed / kGravity; }

}  // namespace

double directional_spreading(const glm::dvec2& k, double wind_direction_deg) {
    const double length = glm::length(k);
    if (length == 0.0) {
        return 0.0;
    }
    const double a = wind_direction_deg * (kPi / 180.0);
    const double cos_theta = glm::dot(k / length, glm::dvec2(std::cos(a), std::sin(a)));
    return cos_theta * cos_theta / kPi;
}

double phillips_spectrum(const glm::dvec2& k, const FftOceanSettings& ocean) {
    const double kk = glm::dot(k, k);
    if (kk == 0.0) {
        return 0.0;
    }
    const double large = largest_wave(ocean);
    const double small = large / 1000.0;
    const double omnidirectional_over_k = 0.5 * kPhillipsAlpha * std::exp(-1.0 / (kk * large * large)) / (kk * kk);
    return omnidirectional_over_k * directional_spreading(k, ocean.wind_direction_deg) * std::exp(-kk * small * small);
}

JonswapParameters jonswap_parameters(const FftOceanSettings& ocean) {
    const double v = ocean.wind_speed;
    return {0.076 * std::pow(v * v / (ocean.fetch * kGravity), 0.22),
            22.0 * std::cbrt(kGravity * kGravity / (v * ocean.fetch))};
}

double jonswap_frequency_spectrum(double omega, const FftOceanSettings& ocean) {
    const JonswapParameters p = jonswap_parameters(ocean);
    if (!(omega > 0.0) || p.omega_peak / omega > 8.0) {
        return 0.0;  // exp(-5/4 8^4) underflows; avoids 0 * inf as omega -> 0
    }
    const double sigma = omega <= p.omega_peak ? kJonswapSigmaBelowPeak : kJonswapSigmaAbovePeak;
    const double offset = (omega - p.omega_peak) / (sigma * p.omega_peak);
    const double r = std::exp(-0.5 * offset * offset);
    return p.alpha * kGravity * kGravity / std::pow(omega, 5) * std::exp(-1.25 * std::pow(p.omega_peak / omega, 4)) *
           std::pow(kJonswapGamma, r);
}

double jonswap_spectrum(const glm::dvec2& k, const FftOceanSettings& ocean) {
    const double length = glm::length(k);
    if (length == 0.0) {
        return 0.0;
    }
    const double omega = std::sqrt(kGravity * length);
    const double domega_dk = kGravity / (2.0 * omega);
    return jonswap_frequency_spectrum(omega, ocean) * domega_dk * directional_spreading(k, ocean.wind_direction_deg) /
           length;
}

double ocean_spectrum(const glm::dvec2& k, const FftOceanSettings& ocean) {
    const double scale2 = ocean.amplitude_scale * ocean.amplitude_scale;
    switch (ocean.spectrum) {
        case OceanSpectrum::Phillips: return scale2 * phillips_spectrum(k, ocean);
        case OceanSpectrum::Jonswap: return scale2 * jonswap_spectrum(k, ocean);
    }
    return 0.0;
}

double phillips_variance(const FftOceanSettings& ocean) {
    const double large = largest_wave(ocean);
    return kPhillipsAlpha * large * large / 4.0 * ocean.amplitude_scale * ocean.amplitude_scale;
}

}  // namespace vkw
