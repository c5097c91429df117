// Exact evaluation of the FFT ocean's Fourier series (fft_ocean_surface.hpp).
#include "engine/water/fft_ocean_surface.hpp"

#include <cmath>
#include <cstddef>
#include <numbers>
#include <utility>

namespace vkw {

namespace {

// exp(i 2 pi f u) for every signed frequency f of an n-point grid, u = x / period reduced to
// [0, 1) first: the phase stays accurate far from the origin and the series exactly periodic.
std::vector<std::complex<double>> phase_factors(double x, double period, uint32_t n) {
    const double u = x / period - std::floor(x / period);
    std::vector<std::complex<double>> factors(n);
    for (uint32_t a = 0; a < n; ++a) {
        const double turns = FftOceanSpectrum::frequency(a, n) * u;
        factors[a] = std::polar(1.0, 2.0 * std::numbers::pi * (turns - std::round(turns)));
    }
    return factors;
}

}  // namespace

FftOceanSurface::FftOceanSurface(std::shared_ptr<const FftOceanSpectrum> spectrum, double choppiness, double level,
                                 double time)
    : spectrum_(std::move(spectrum)),
      choppiness_(choppiness),
      level_(level),
      time_(time),
      modes_(ocean_modes_at(*spectrum_, time)) {
    for (const std::complex<double>& mode : modes_) {
        amplitude_bound_ += std::abs(mode);
    }
}

OceanFieldValues FftOceanSurface::fields_at(double x0, double z0) const {
    const uint32_t n = spectrum_->n;
    const std::vector<std::complex<double>> ex = phase_factors(x0, spectrum_->patch_size, n);
    const std::vector<std::complex<double>> ez = phase_factors(z0, spectrum_->patch_size, n);
    OceanFieldValues sum{};
    for (uint32_t b = 0; b < n; ++b) {
        for (uint32_t a = 0; a < n; ++a) {
            const std::complex<double> mode = modes_[std::size_t(b) * n + a];
            if (mode == 0.0) {
                continue;  // the Nyquist row and column, k = 0, and empty spectra
            }
            const std::complex<double> term = mode * ex[a] * ez[b];
            const OceanFieldMultipliers m = ocean_field_multipliers(spectrum_->wave_vector(a, b), choppiness_);
            for (uint32_t f = 0; f < kOceanFieldCount; ++f) {
                sum[f] += (m[f] * term).real();
            }
        }
    }
    return sum;
}

SurfacePoint FftOceanSurface::at_parameter(double x0, double z0) const {
    return ocean_surface_point(fields_at(x0, z0), x0, z0, level_);
}

FftOceanGrid FftOceanSurface::grid() const { return evaluate_ocean_grid(*spectrum_, choppiness_, time_); }

}  // namespace vkw
