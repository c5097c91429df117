// The FFT ocean's initial spectrum, its time evolution and the per-field multipliers
// (fft_ocean.hpp).
#include "engine/water/fft_ocean.hpp"

#include <cmath>
#include <mutex>
#include <numbers>
#include <optional>
#include <utility>

#include "engine/water/counter_rng.hpp"
#include "engine/water/ocean_spectrum.hpp"
#include "engine/water/validate_waves.hpp"

namespace vkw {

int FftOceanSpectrum::frequency(uint32_t index, uint32_t count) {
    return index < count / 2 ? int(index) : int(index) - int(count);
}

glm::dvec2 FftOceanSpectrum::wave_vector(uint32_t a, uint32_t b) const {
    const double dk = 2.0 * std::numbers::pi / patch_size;
    return dk * glm::dvec2(frequency(a, n), frequency(b, n));
}

std::size_t FftOceanSpectrum::opposite(std::size_t index) const {
    const std::size_t a = index % n, b = index / n;
    return ((n - b) % n) * n + (n - a) % n;
}

double FftOceanSpectrum::amplitude_bound() const {
    double sum = 0.0;
    for (const std::complex<double>& mode : h0) {
        sum += std::abs(mode);
    }
    return 2.0 * sum;
}

double FftOceanSpectrum::curvature_rms() const {
    double sum = 0.0;
    for (uint32_t b = 0; b < n; ++b) {
        for (uint32_t a = 0; a < n; ++a) {
            const glm::dvec2 k = wave_vector(a, b);
            sum += std::norm(h0[std::size_t(b) * n + a]) * glm::dot(k, k) * glm::dot(k, k);
        }
    }
    return std::sqrt(2.0 * sum);
}

FftOceanSpectrum make_ocean_spectrum(const FftOceanSettings& ocean, uint64_t seed) {
    validate_ocean(ocean);
    FftOceanSpectrum spectrum;
    spectrum.n = ocean.resolution;
    spectrum.patch_size = ocean.patch_size;
    const uint32_t n = spectrum.n;
    const double dk = 2.0 * std::numbers::pi / ocean.patch_size;
    spectrum.h0.assign(std::size_t(n) * n, {0.0, 0.0});
    for (uint32_t b = 0; b < n; ++b) {
        for (uint32_t a = 0; a < n; ++a) {
            if (a == n / 2 || b == n / 2) {
                continue;  // Nyquist row and column stay zero (see the header)
            }
            const int fx = FftOceanSpectrum::frequency(a, n);
            const int fz = FftOceanSpectrum::frequency(b, n);
            const std::array<double, 2> xi = gaussian_pair(seed, fx, fz);
            const double psi = ocean_spectrum(spectrum.wave_vector(a, b), ocean);
            spectrum.h0[std::size_t(b) * n + a] = std::complex<double>(xi[0], xi[1]) * (std::sqrt(psi) * dk * 0.5);
        }
    }
    return spectrum;
}

double ocean_angular_frequency(const glm::dvec2& k) { return std::sqrt(kGravity * glm::length(k)); }

std::vector<std::complex<double>> ocean_modes_at(const FftOceanSpectrum& spectrum, double time) {
    const uint32_t n = spectrum.n;
    std::vector<std::complex<double>> modes(spectrum.h0.size());
    for (uint32_t b = 0; b < n; ++b) {
        for (uint32_t a = 0; a < n; ++a) {
            const std::size_t i = std::size_t(b) * n + a;
            const std::complex<double> rotation =
                std::polar(1.0, ocean_angular_frequency(spectrum.wave_vector(a, b)) * time);
            modes[i] = spectrum.h0[i] * rotation + std::conj(spectrum.h0[spectrum.opposite(i)]) * std::conj(rotation);
        }
    }
    return modes;
}

OceanFieldMultipliers ocean_field_multipliers(const glm::dvec2& k, double choppiness) {
    OceanFieldMultipliers m{};
    const double length = glm::length(k);
    if (length == 0.0) {
        return m;
    }
    const std::complex<double> i(0.0, 1.0);
    const double c = choppiness / length;
    m[kOceanHeight] = 1.0;
    m[kOceanDispX] = i * c * k.x;
    m[kOceanDispZ] = i * c * k.y;
    m[kOceanSlopeX] = i * k.x;
    m[kOceanSlopeZ] = i * k.y;
    // d/dx0 multiplies a mode by i kx: (i kx) (i c kx) = -c kx^2, and so on.
    m[kOceanDispXdX] = -c * k.x * k.x;
    m[kOceanDispXdZ] = -c * k.x * k.y;
    m[kOceanDispZdZ] = -c * k.y * k.y;
    return m;
}

SurfacePoint ocean_surface_point(const OceanFieldValues& f, double x0, double z0, double level) {
    const glm::dvec3 position(x0 + f[kOceanDispX], level + f[kOceanHeight], z0 + f[kOceanDispZ]);
    const glm::dvec3 dP_du(1.0 + f[kOceanDispXdX], f[kOceanSlopeX], f[kOceanDispXdZ]);
    const glm::dvec3 dP_dv(f[kOceanDispXdZ], f[kOceanSlopeZ], 1.0 + f[kOceanDispZdZ]);
    return make_surface_point(position, dP_du, dP_dv);
}

std::shared_ptr<const FftOceanSpectrum> shared_ocean_spectrum(const FftOceanSettings& ocean, uint64_t seed) {
    FftOceanSettings shape = ocean;
    shape.choppiness = 0.0;  // scales the displacement at evaluation, not h0
    static std::mutex mutex;
    static std::optional<std::pair<FftOceanSettings, uint64_t>> last_key;
    static std::shared_ptr<const FftOceanSpectrum> last;
    const std::lock_guard lock(mutex);
    if (!last_key || last_key->first != shape || last_key->second != seed) {
        last = std::make_shared<const FftOceanSpectrum>(make_ocean_spectrum(ocean, seed));
        last_key = std::make_pair(shape, seed);
    }
    return last;
}

}  // namespace vkw
