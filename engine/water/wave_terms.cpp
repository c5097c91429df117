// Per-wave constants of the wave sum (wave_terms.hpp).
#include "engine/water/wave_terms.hpp"

#include <cmath>
#include <numbers>

namespace vkw {

namespace {

double radians(double degrees) { return degrees * (std::numbers::pi / 180.0); }

}  // namespace

WaveTerms wave_terms(const WaveComponent& c, double time) {
    const double k = 2.0 * std::numbers::pi / c.wavelength;
    const double omega = c.speed < 0.0 ? std::sqrt(kGravity * k) : c.speed * k;
    const double a = radians(c.direction_deg);
    WaveTerms w;
    w.k_vector = k * glm::dvec2(std::cos(a), std::sin(a));
    w.phase_at_origin = radians(c.phase_deg) - omega * time;
    w.amplitude = c.amplitude;
    w.displacement_scale = c.steepness / (k * k);
    return w;
}

}  // namespace vkw
