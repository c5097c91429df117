// The FFT ocean sampled by zero-padded inverse FFTs and interpolated by tensor cubic Hermite
// patches (sampled_ocean_surface.hpp).
#include "engine/water/sampled_ocean_surface.hpp"

#include <algorithm>
#include <cmath>
#include <complex>
#include <limits>
#include <numbers>
#include <string>

#include "engine/core/errors.hpp"
#include "engine/core/parallel.hpp"
#include "engine/water/fft.hpp"

namespace vkw {

namespace {

// The multiplier of mode k for Hermite datum d of a field (value, d/dx0, d/dz0, d2/dx0dz0).
std::complex<double> hermite_multiplier(uint32_t datum, const glm::dvec2& k) {
    const std::complex<double> i(0.0, 1.0);
    switch (datum) {
        case 0: return 1.0;
        case 1: return i * k.x;
        case 2: return i * k.y;
        default: return -k.x * k.y;
    }
}

// Cubic Hermite basis on [0, 1] at t: the value weights of the left and right node and the
// slope weights (to be multiplied by the spacing).
struct HermiteBasis {
    double value[2];
    double slope[2];
};
HermiteBasis hermite_basis(double t) {
    const double t2 = t * t, t3 = t2 * t;
    return {{2.0 * t3 - 3.0 * t2 + 1.0, -2.0 * t3 + 3.0 * t2}, {t3 - 2.0 * t2 + t, t3 - t2}};
}

}  // namespace

SampledOceanSurface::SampledOceanSurface(const FftOceanSpectrum& spectrum, double choppiness, double level, double time,
                                         uint32_t padding)
    : level_(level), heightfield_(choppiness == 0.0) {
    const uint32_t n = spectrum.n;
    if (padding == 0 || (padding & (padding - 1)) != 0) {
        throw InternalError("SampledOceanSurface: padding " + std::to_string(padding) + " must be a power of two >= 1");
    }
    samples_ = n * padding;
    period_ = spectrum.patch_size;
    const double h = spacing();
    const std::vector<std::complex<double>> modes = ocean_modes_at(spectrum, time);

    // Spectral sums for the bounds: sum |m_f h~| |kx|^a |kz|^b per field.
    OceanFieldValues sum_abs{}, fourth_x{}, fourth_z{}, mixed{};
    double largest_k = 0.0;
    for (uint32_t b = 0; b < n; ++b) {
        for (uint32_t a = 0; a < n; ++a) {
            const std::complex<double> mode = modes[std::size_t(b) * n + a];
            if (mode == 0.0) continue;
            const glm::dvec2 k = spectrum.wave_vector(a, b);
            largest_k = std::max(largest_k, glm::length(k));
            const OceanFieldMultipliers m = ocean_field_multipliers(k, choppiness);
            const double kx = std::abs(k.x), kz = std::abs(k.y);
            for (uint32_t f = 0; f < kOceanFieldCount; ++f) {
                const double c = std::abs(m[f] * mode);
                sum_abs[f] += c;
                fourth_x[f] += c * kx * kx * kx * kx;
                fourth_z[f] += c * kz * kz * kz * kz;
                mixed[f] += c * kx * kz * kz * kz * kz;
            }
        }
    }
    shortest_wavelength_ =
        largest_k > 0.0 ? 2.0 * std::numbers::pi / largest_k : std::numeric_limits<double>::infinity();
    // Rounding of the padded FFT: log2(N) butterfly stages, each adding a few ulps of the
    // magnitudes it combines, which are at most sum |m_f h~|: 8 log2(N) eps sum |m_f h~|.
    const double fft_rounding = 8.0 * std::log2(double(samples_)) * std::numeric_limits<double>::epsilon();
    for (uint32_t f = 0; f < kOceanFieldCount; ++f) {
        error_bound_[f] =
            std::pow(h, 4) / 384.0 * (fourth_x[f] + fourth_z[f] + 0.25 * h * mixed[f]) + fft_rounding * sum_abs[f];
    }

    // One zero-padded inverse FFT per (field, Hermite datum); the fields run on their own threads.
    const std::size_t count = std::size_t(samples_) * samples_;
    nodes_.assign(count * kOceanFieldCount * kHermiteData, 0.0);
    auto transform_field = [&](uint32_t f) {
        std::vector<std::complex<double>> padded(count);
        for (uint32_t datum = 0; datum < kHermiteData; ++datum) {
            std::fill(padded.begin(), padded.end(), std::complex<double>(0.0));
            for (uint32_t b = 0; b < n; ++b) {
                for (uint32_t a = 0; a < n; ++a) {
                    const std::complex<double> mode = modes[std::size_t(b) * n + a];
                    if (mode == 0.0) continue;
                    const glm::dvec2 k = spectrum.wave_vector(a, b);
                    // Signed frequency f lands at index f mod N of the padded spectrum.
                    const uint32_t pa = uint32_t(FftOceanSpectrum::frequency(a, n) + int(samples_)) % samples_;
                    const uint32_t pb = uint32_t(FftOceanSpectrum::frequency(b, n) + int(samples_)) % samples_;
                    padded[std::size_t(pb) * samples_ + pa] =
                        ocean_field_multipliers(k, choppiness)[f] * hermite_multiplier(datum, k) * mode;
                }
            }
            fft_inverse_2d(padded, samples_);
            for (std::size_t i = 0; i < count; ++i) {
                nodes_[(i * kOceanFieldCount + f) * kHermiteData + datum] = padded[i].real();
            }
        }
    };
    const unsigned threads = std::min<unsigned>(kOceanFieldCount, hardware_threads());
    run_on_threads(threads, [&](unsigned t) {
        for (uint32_t f = t; f < kOceanFieldCount; f += threads) transform_field(f);
    });

    // The interpolant's amplitude bound and the largest slope at the samples.
    double max_value = 0.0, max_dx = 0.0, max_dz = 0.0, max_dxz = 0.0;
    for (uint32_t iz = 0; iz < samples_; ++iz) {
        for (uint32_t ix = 0; ix < samples_; ++ix) {
            const double* height = node(ix, iz) + kOceanHeight * kHermiteData;
            max_value = std::max(max_value, std::abs(height[0]));
            max_dx = std::max(max_dx, std::abs(height[1]));
            max_dz = std::max(max_dz, std::abs(height[2]));
            max_dxz = std::max(max_dxz, std::abs(height[3]));
            const SurfacePoint p = at_parameter(ix * h, iz * h);
            max_sample_slope_ = std::max(max_sample_slope_, std::hypot(p.normal.x, p.normal.z) / p.normal.y);
        }
    }
    amplitude_bound_ = max_value + 0.25 * h * (max_dx + max_dz) + h * h / 16.0 * max_dxz;
}

OceanFieldValues SampledOceanSurface::fields_at(double x0, double z0) const {
    // The cell and the position in it; the grid wraps with the period.
    const double u = x0 / spacing(), v = z0 / spacing();
    const double cell_u = std::floor(u), cell_v = std::floor(v);
    const HermiteBasis bx = hermite_basis(u - cell_u), bz = hermite_basis(v - cell_v);
    const auto wrap = [&](double cell) {
        const double m = std::fmod(cell, double(samples_));
        return uint32_t(m < 0.0 ? m + samples_ : m);
    };
    const uint32_t ix[2] = {wrap(cell_u), wrap(cell_u + 1.0)};
    const uint32_t iz[2] = {wrap(cell_v), wrap(cell_v + 1.0)};
    const double h = spacing();
    OceanFieldValues values{};
    for (int cz = 0; cz < 2; ++cz) {
        for (int cx = 0; cx < 2; ++cx) {
            // Weights of value, d/dx0, d/dz0 and d2/dx0dz0 at this corner.
            const double w[kHermiteData] = {bx.value[cx] * bz.value[cz], h * bx.slope[cx] * bz.value[cz],
                                            h * bx.value[cx] * bz.slope[cz], h * h * bx.slope[cx] * bz.slope[cz]};
            const double* data = node(ix[cx], iz[cz]);
            for (uint32_t f = 0; f < kOceanFieldCount; ++f) {
                const double* d = data + f * kHermiteData;
                values[f] += w[0] * d[0] + w[1] * d[1] + w[2] * d[2] + w[3] * d[3];
            }
        }
    }
    return values;
}

SurfacePoint SampledOceanSurface::at_parameter(double x0, double z0) const {
    return ocean_surface_point(fields_at(x0, z0), x0, z0, level_);
}

}  // namespace vkw
