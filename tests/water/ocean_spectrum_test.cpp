// The FFT ocean's variance spectra: normalisation (the discrete sum of Psi dk^2 against the
// closed-form integral), JONSWAP's parameters and its change of variables from w to k, and
// the realised variance of one ocean against its expectation (Parseval).
#include <cmath>
#include <complex>
#include <cstddef>
#include <numbers>

#include <gtest/gtest.h>

#include "engine/water/fft_ocean.hpp"
#include "engine/water/ocean_grid.hpp"
#include "engine/water/ocean_spectrum.hpp"

namespace vkw {
namespace {

constexpr double kPi = std::numbers::pi;

// sum of Psi(k) dk^2 over the modes an n x n grid keeps (no Nyquist row/column, no k = 0).
double discrete_variance(const FftOceanSettings& ocean) {
    const uint32_t n = ocean.resolution;
    const double dk = 2.0 * kPi / ocean.patch_size;
    double sum = 0.0;
    for (uint32_t b = 0; b < n; ++b) {
        for (uint32_t a = 0; a < n; ++a) {
            if (a == n / 2 || b == n / 2) continue;
            const glm::dvec2 k = dk * glm::dvec2(FftOceanSpectrum::frequency(a, n), FftOceanSpectrum::frequency(b, n));
            sum += ocean_spectrum(k, ocean) * dk * dk;
        }
    }
    return sum;
}

TEST(water_ocean_spectrum, PhillipsSumMatchesItsClosedFormIntegral) {
    FftOceanSettings ocean;
    ocean.resolution = 1024;
    ocean.patch_size = 1000.0;  // dk = 0.0063 rad/m, 17 steps below the peak at 1 / (sqrt 2 L)
    ocean.wind_speed = 8.0;     // L = 6.52 m
    ocean.amplitude_scale = 1.5;
    const double expected = phillips_variance(ocean);
    // What the grid misses: the tail beyond k_max = pi n / patch = 3.2 rad/m, where
    // Psi ~ alpha / (2 pi) cos^2 / k^4, holds (alpha / 4) / k_max^2 of the variance, a
    // relative 1 / (k_max L)^2 = 0.23% (the corners of the square add some back); the
    // small-wave suppression takes 1.4e-5; the Riemann sum of the smooth peak errs far less.
    const double large = 8.0 * 8.0 / kGravity, k_max = kPi * 1024 / 1000.0;
    const double tail = 1.0 / ((k_max * large) * (k_max * large));
    const double sum = discrete_variance(ocean);
    EXPECT_LT(sum, expected);
    EXPECT_NEAR(sum / expected, 1.0, tail + 1e-4);
}

TEST(water_ocean_spectrum, DensitiesAreEvenAndZeroAcrossTheWind) {
    FftOceanSettings ocean;
    ocean.wind_direction_deg = 30.0;
    for (OceanSpectrum model : {OceanSpectrum::Phillips, OceanSpectrum::Jonswap}) {
        ocean.spectrum = model;
        const glm::dvec2 k(0.3, -0.2);
        EXPECT_EQ(ocean_spectrum(k, ocean), ocean_spectrum(-k, ocean));
        EXPECT_EQ(ocean_spectrum(glm::dvec2(0.0), ocean), 0.0);
        const double a = 30.0 * kPi / 180.0;
        const glm::dvec2 across = 0.5 * glm::dvec2(-std::sin(a), std::cos(a));
        EXPECT_NEAR(ocean_spectrum(across, ocean), 0.0, 1e-30);
    }
}

TEST(water_ocean_spectrum, JonswapParametersFollowTheFetchLaws) {
    FftOceanSettings ocean;
    ocean.wind_speed = 10.0;
    ocean.fetch = 100000.0;
    // alpha = 0.076 (V^2 / (F g))^0.22, w_p = 22 (g^2 / (V F))^(1/3), worked by hand.
    const JonswapParameters p = jonswap_parameters(ocean);
    EXPECT_NEAR(p.alpha, 0.0100611, 1e-7);
    EXPECT_NEAR(p.omega_peak, 1.0081737, 1e-7);
    // At the peak r = 1: S = alpha g^2 w_p^-5 exp(-5/4) gamma, and the peak is the maximum.
    const double at_peak = jonswap_frequency_spectrum(p.omega_peak, ocean);
    EXPECT_NEAR(at_peak, p.alpha * kGravity * kGravity * std::pow(p.omega_peak, -5) * std::exp(-1.25) * 3.3,
                1e-12 * at_peak);
    EXPECT_LT(jonswap_frequency_spectrum(0.98 * p.omega_peak, ocean), at_peak);
    EXPECT_LT(jonswap_frequency_spectrum(1.02 * p.omega_peak, ocean), at_peak);
}

TEST(water_ocean_spectrum, JonswapDensityIntegratesBackToTheFrequencySpectrum) {
    // Over the ring of wave vectors with w(k) = w: integral of Psi(k) k dtheta, times
    // dk/dw = 2 w / g, must give S(w) back (the directional spreading integrates to 1).
    // 64 equally spaced angles integrate cos^2 exactly.
    FftOceanSettings ocean;
    ocean.spectrum = OceanSpectrum::Jonswap;
    ocean.wind_direction_deg = 75.0;
    for (double omega : {0.7, 1.0, 1.086, 1.3, 2.5, 6.0}) {
        const double k = omega * omega / kGravity;
        double ring = 0.0;
        const int count = 64;
        for (int i = 0; i < count; ++i) {
            const double theta = 2.0 * kPi * i / count;
            ring += jonswap_spectrum(k * glm::dvec2(std::cos(theta), std::sin(theta)), ocean) * k * (2.0 * kPi / count);
        }
        const double expected = jonswap_frequency_spectrum(omega, ocean);
        EXPECT_NEAR(ring * 2.0 * omega / kGravity, expected, 1e-12 * expected) << "w = " << omega;
    }
}

TEST(water_ocean_spectrum, RealisedVarianceMatchesTheSpectrum) {
    FftOceanSettings ocean;
    ocean.resolution = 64;
    ocean.patch_size = 200.0;
    ocean.wind_speed = 7.0;
    const FftOceanSpectrum spectrum = make_ocean_spectrum(ocean, 2024);
    const FftOceanGrid grid = evaluate_ocean_grid(spectrum, 0.0, 3.0);
    double mean_square = 0.0;
    for (double h : grid.fields[kOceanHeight]) mean_square += h * h;
    mean_square /= double(grid.fields[kOceanHeight].size());
    // Parseval on the grid: the mean of h^2 is exactly the sum of |h~(k, t)|^2.
    double modes_power = 0.0;
    for (const auto& m : ocean_modes_at(spectrum, 3.0)) modes_power += std::norm(m);
    EXPECT_NEAR(mean_square, modes_power, 1e-12 * modes_power);
    // Its expectation is sum Psi dk^2. Each pair (k, -k) contributes 2 |h~(k)|^2, where
    // h~(k) is a circular gaussian of variance a_p = E|h0(k)|^2 + E|h0(-k)|^2: an
    // exponential of mean and deviation a_p. So the relative standard deviation of the
    // realised variance is sqrt(sum a_p^2) / sum a_p (a few dominant modes make it large);
    // the test allows four of them.
    const double dk = 2.0 * kPi / ocean.patch_size;
    double sum_a = 0.0, sum_a2 = 0.0;
    const uint32_t n = ocean.resolution;
    for (uint32_t b = 0; b < n; ++b) {
        for (uint32_t a = 0; a < n; ++a) {
            const int fx = FftOceanSpectrum::frequency(a, n), fz = FftOceanSpectrum::frequency(b, n);
            if (a == n / 2 || b == n / 2 || fz < 0 || (fz == 0 && fx <= 0)) continue;        // one per pair
            const double a_p = ocean_spectrum(spectrum.wave_vector(a, b), ocean) * dk * dk;  // Psi dk^2 / 2 twice
            sum_a += a_p;
            sum_a2 += a_p * a_p;
        }
    }
    const double expected = 2.0 * sum_a;
    const double relative_sigma = std::sqrt(sum_a2) / sum_a;
    EXPECT_NEAR(expected, discrete_variance(ocean), 1e-12 * expected);
    EXPECT_NEAR(mean_square / expected, 1.0, 4.0 * relative_sigma) << "relative sigma " << relative_sigma;
}

}  // namespace
}  // namespace vkw
