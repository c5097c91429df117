// Sum of sine and Gerstner waves: positions and analytic tangents (wave_sum_surface.hpp).
#include "engine/water/wave_sum_surface.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <numbers>

#include "engine/water/validate_waves.hpp"

namespace vkw {

namespace {

// G = max over unit u of sum A k |d . u|, from directions u every 2 pi / K: between two of them
// sum A k |d . u| changes by at most (pi / K) sum A k, which is added.
double height_gradient_bound(const std::vector<WaveTerms>& waves) {
    constexpr int kDirections = 720;
    // The directions once per process, and the last waves' bound once per thread: the renderer
    // builds the same waves' surface several times a frame (its needs, its bounds), each at a
    // new time, and the search was most of that. The bound reads only the amplitudes and the
    // wave vectors, which the clock does not move.
    static const std::array<glm::dvec2, kDirections> directions = [] {
        std::array<glm::dvec2, kDirections> table;
        for (int i = 0; i < kDirections; ++i) {
            const double angle = 2.0 * std::numbers::pi * i / kDirections;
            table[std::size_t(i)] = glm::dvec2(std::cos(angle), std::sin(angle));
        }
        return table;
    }();
    thread_local std::vector<glm::dvec3> last_waves;  // (A, k_vector) per wave
    thread_local double last_bound = 0.0;
    const bool same =
        last_waves.size() == waves.size() &&
        std::equal(waves.begin(), waves.end(), last_waves.begin(),
                   [](const WaveTerms& w, const glm::dvec3& l) { return l == glm::dvec3(w.amplitude, w.k_vector); });
    if (same && !waves.empty()) return last_bound;
    double terms = 0.0, height_gradient = 0.0;
    for (const WaveTerms& w : waves) terms += w.amplitude * glm::length(w.k_vector);
    for (const glm::dvec2& u : directions) {
        double along = 0.0;
        for (const WaveTerms& w : waves) along += w.amplitude * std::abs(glm::dot(w.k_vector, u));
        height_gradient = std::max(height_gradient, along);
    }
    last_waves.clear();
    for (const WaveTerms& w : waves) last_waves.emplace_back(w.amplitude, w.k_vector);
    last_bound = std::min(terms, height_gradient + std::numbers::pi / kDirections * terms);
    return last_bound;
}

}  // namespace

WaveSumSurface::WaveSumSurface(const WaveSettings& settings, double level, double time) : level_(level) {
    validate_wave_components(settings);
    waves_.reserve(settings.components.size());
    double steepness = 0.0;
    for (const WaveComponent& c : settings.components) {
        waves_.push_back(wave_terms(c, time));
        amplitude_sum_ += c.amplitude;
        steepness += c.steepness;
        heightfield_ = heightfield_ && c.steepness == 0.0;
    }
    const double height_gradient = height_gradient_bound(waves_);
    slope_bound_ = steepness < 1.0 ? height_gradient / (1.0 - steepness) : std::numeric_limits<double>::infinity();
    if (heightfield_) {
        for (const WaveTerms& w : waves_) {
            curvature_bound_ += w.amplitude * glm::dot(w.k_vector, w.k_vector);
        }
    } else {
        curvature_bound_ = std::numeric_limits<double>::infinity();
    }
}

SurfacePoint WaveSumSurface::at_parameter(double x0, double z0) const {
    glm::dvec3 position(x0, level_, z0);
    glm::dvec3 dP_du(1.0, 0.0, 0.0);
    glm::dvec3 dP_dv(0.0, 0.0, 1.0);
    for (const WaveTerms& w : waves_) {
        const double theta = glm::dot(w.k_vector, glm::dvec2(x0, z0)) + w.phase_at_origin;
        const double s = std::sin(theta);
        const double c = std::cos(theta);
        const double kx = w.k_vector.x, kz = w.k_vector.y;
        // D = (s / k) d cos(theta) = (s / k^2) k_vector cos(theta), and d(theta)/du = kx.
        const double q = w.displacement_scale;
        position += glm::dvec3(q * kx * c, w.amplitude * s, q * kz * c);
        dP_du += glm::dvec3(-q * kx * kx * s, w.amplitude * kx * c, -q * kx * kz * s);
        dP_dv += glm::dvec3(-q * kx * kz * s, w.amplitude * kz * c, -q * kz * kz * s);
    }
    return make_surface_point(position, dP_du, dP_dv);
}

}  // namespace vkw
