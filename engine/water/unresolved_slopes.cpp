// The unresolved slopes' covariance table (unresolved_slopes.hpp).
#include "engine/water/unresolved_slopes.hpp"

#include <algorithm>
#include <cmath>
#include <memory>
#include <mutex>
#include <numbers>
#include <vector>

#include "engine/water/fft_ocean.hpp"

namespace vkw {
namespace {

// A component's contribution to the covariance before its weight: its slope amplitude squared
// over its direction, (S_xx, S_xz, S_zz).
struct SlopeTerm {
    double k;  // |k|, rad/m
    glm::dvec3 covariance;
};

UnresolvedSlopeTable table_from_terms(const std::vector<SlopeTerm>& terms) {
    UnresolvedSlopeTable table;
    double k_min = INFINITY, k_max = 0.0;
    for (const SlopeTerm& term : terms) {
        if (!(term.covariance.x + term.covariance.z > 0.0)) continue;
        table.total_variance += term.covariance.x + term.covariance.z;
        k_min = std::min(k_min, term.k);
        k_max = std::max(k_max, term.k);
    }
    if (!(k_max > 0.0)) return UnresolvedSlopeTable{};
    // From the cutoff at which the longest wave is all but unresolved (weight 0.9 at k_c = k_min / 2)
    // up to the one at which the shortest is all but resolved (weight 0.002 at 30 k_max); outside,
    // the end entries stand.
    table.any = true;
    table.log_k0 = std::log(0.5 * k_min);
    table.log_step = (std::log(30.0 * k_max) - table.log_k0) / double(kUnresolvedSlopeEntries - 1);
    for (std::size_t i = 0; i < kUnresolvedSlopeEntries; ++i) {
        const double cutoff = std::exp(table.log_k0 + double(i) * table.log_step);
        glm::dvec3 sum(0.0);
        for (const SlopeTerm& term : terms) sum += unresolved_weight(term.k / cutoff) * term.covariance;
        table.entries[i] = glm::vec4(glm::vec3(sum), float(cutoff));
    }
    return table;
}

std::vector<SlopeTerm> sine_terms(const std::vector<WaveComponent>& components) {
    std::vector<SlopeTerm> terms;
    for (const WaveComponent& wave : components) {
        const double k = 2.0 * std::numbers::pi / wave.wavelength;
        const double a = wave.direction_deg * (std::numbers::pi / 180.0);
        const glm::dvec2 d(std::cos(a), std::sin(a));
        const double slope_variance = 0.5 * wave.amplitude * wave.amplitude * k * k;
        terms.push_back({k, slope_variance * glm::dvec3(d.x * d.x, d.x * d.y, d.y * d.y)});
    }
    return terms;
}

std::vector<SlopeTerm> ocean_terms(const FftOceanSpectrum& spectrum) {
    std::vector<SlopeTerm> terms;
    terms.reserve(spectrum.h0.size());
    for (uint32_t b = 0; b < spectrum.n; ++b) {
        for (uint32_t a = 0; a < spectrum.n; ++a) {
            const std::complex<double> h0 = spectrum.h0[std::size_t(b) * spectrum.n + a];
            const double power = 2.0 * std::norm(h0);
            if (power == 0.0) continue;
            const glm::dvec2 k = spectrum.wave_vector(a, b);
            terms.push_back({glm::length(k), power * glm::dvec3(k.x * k.x, k.x * k.y, k.y * k.y)});
        }
    }
    return terms;
}

}  // namespace

double unresolved_weight(double k_over_cutoff) {
    // The share of a sine's slope variance that varies within a box of side w = pi / k_c around a
    // random phase: 1 - sinc^2(k w / 2), with k w / 2 = (pi / 2) k / k_c.
    const double x = 0.5 * std::numbers::pi * k_over_cutoff;
    if (x < 1e-4) return x * x / 3.0;
    const double sinc = std::sin(x) / x;
    return 1.0 - sinc * sinc;
}

UnresolvedSlopeTable unresolved_slope_table(const WaveSettings& waves) {
    switch (waves.model) {
        case WaveModel::Flat: return {};
        case WaveModel::Sum: return table_from_terms(sine_terms(waves.components));
        case WaveModel::FftOcean: {
            const std::shared_ptr<const FftOceanSpectrum> spectrum = shared_ocean_spectrum(waves.ocean, waves.seed);
            static std::mutex mutex;
            static std::shared_ptr<const FftOceanSpectrum> last_spectrum;
            static UnresolvedSlopeTable last_table;
            const std::lock_guard lock(mutex);
            if (spectrum != last_spectrum) {
                last_table = table_from_terms(ocean_terms(*spectrum));
                last_spectrum = spectrum;
            }
            return last_table;
        }
    }
    return {};
}

}  // namespace vkw
