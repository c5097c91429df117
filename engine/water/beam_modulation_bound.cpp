// The bound on the waves' modulation of the sun's irradiance in the water (beam_modulation_bound.hpp).
#include "engine/water/beam_modulation_bound.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <numbers>
#include <vector>

namespace vkw {
namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();

// What the sunlight does at one surface normal: the transmittance, and the refracted ray's angle
// phi from the vertical as 1 / cos(phi) and tan(phi), and K (beam_modulation_bound.hpp).
struct Refraction {
    double transmittance, inverse_cos_phi, tan_phi, focusing;
};

// Air (n = 1) into water (n >= 1): no total internal reflection. cos_i > 0.
Refraction refract_sun(const glm::dvec3& sun, const glm::dvec3& normal, double n) {
    const double cos_i = -glm::dot(sun, normal);
    const double cos_t = std::sqrt(1.0 - (1.0 - cos_i * cos_i) / (n * n));
    const double s_perp = (cos_i - n * cos_t) / (cos_i + n * cos_t);
    const double s_par = (n * cos_i - cos_t) / (n * cos_i + cos_t);
    const glm::dvec3 t = sun / n + (cos_i / n - cos_t) * normal;
    const double cos_phi = -t.y;
    const double sin_phi = std::sqrt(std::max(0.0, 1.0 - cos_phi * cos_phi));
    return {1.0 - 0.5 * (s_perp * s_perp + s_par * s_par), 1.0 / cos_phi, sin_phi / cos_phi,
            (n * cos_t - cos_i) / (n * cos_t * cos_phi * cos_phi)};
}

// The extremes of one quantity over the sampled tilts, widened by the largest step between
// neighbouring samples (the quantities are smooth in the tilt).
struct Extremes {
    double low = kInfinity, high = -kInfinity, step = 0.0;
    void add(double value) {
        low = std::min(low, value);
        high = std::max(high, value);
    }
    double widened_low() const { return low - step; }
    double widened_high() const { return high + step; }
};

std::string describe(const char* pattern, double value) {
    char text[200];
    std::snprintf(text, sizeof text, pattern, value);
    return text;
}

std::string focusing_reason(double a) {
    return describe(
        "the beams may focus within the lit depth ((D + A) K kappa + S tan(phi) = %.3g >= 1: a caustic can form)", a);
}

}  // namespace

double BeamModulationBound::largest_relative_change() const {
    if (!bounded) return kInfinity;
    return std::max(high - 1.0, 1.0 - low) / low;
}

BeamModulationBound beam_modulation_bound(const BeamModulationInputs& in) {
    BeamModulationBound bound;
    if (!std::isfinite(in.slope) || !std::isfinite(in.curvature) || !std::isfinite(in.amplitude)) {
        bound.unbounded_because = "the wave model gives no bound on its slope or curvature";
        return bound;
    }
    const double cos_s = -in.sun.y;
    const double sun_zenith = std::acos(std::clamp(cos_s, -1.0, 1.0));
    const double max_tilt = std::atan(in.slope);
    if (!(sun_zenith + max_tilt < 0.5 * std::numbers::pi - 1e-3)) {
        bound.unbounded_because = describe("the sun may graze the surface where its slope reaches %.3g", in.slope);
        return bound;
    }
    // The untilted normal alone already shows most caustics: a is at least its value there.
    const Refraction untilted = refract_sun(in.sun, {0.0, 1.0, 0.0}, in.ior);
    const double a_at_least =
        (in.depth + in.amplitude) * std::abs(untilted.focusing) * in.curvature + in.slope * untilted.tan_phi;
    if (!(a_at_least < 1.0)) {
        bound.unbounded_because = focusing_reason(a_at_least);
        return bound;
    }
    // The tilted normals: kTilts magnitudes from 0 to atan(S) (both ends) by kAzimuths directions.
    constexpr int kTilts = 17, kAzimuths = 64;
    std::vector<Refraction> samples(kTilts * kAzimuths);
    for (int j = 0; j < kTilts; ++j) {
        const double tilt = max_tilt * j / (kTilts - 1);
        for (int k = 0; k < kAzimuths; ++k) {
            const double azimuth = 2.0 * std::numbers::pi * k / kAzimuths;
            const glm::dvec3 normal(std::sin(tilt) * std::cos(azimuth), std::cos(tilt),
                                    std::sin(tilt) * std::sin(azimuth));
            samples[j * kAzimuths + k] = refract_sun(in.sun, normal, in.ior);
        }
    }
    Extremes transmittance, inverse_cos_phi, tan_phi, focusing;
    auto widen = [&](const Refraction& a, const Refraction& b) {
        transmittance.step = std::max(transmittance.step, std::abs(a.transmittance - b.transmittance));
        inverse_cos_phi.step = std::max(inverse_cos_phi.step, std::abs(a.inverse_cos_phi - b.inverse_cos_phi));
        tan_phi.step = std::max(tan_phi.step, std::abs(a.tan_phi - b.tan_phi));
        focusing.step = std::max(focusing.step, std::abs(a.focusing - b.focusing));
    };
    for (int j = 0; j < kTilts; ++j) {
        for (int k = 0; k < kAzimuths; ++k) {
            const Refraction& r = samples[j * kAzimuths + k];
            transmittance.add(r.transmittance);
            inverse_cos_phi.add(r.inverse_cos_phi);
            tan_phi.add(r.tan_phi);
            focusing.add(std::abs(r.focusing));
            widen(r, samples[j * kAzimuths + (k + 1) % kAzimuths]);
            if (j + 1 < kTilts) widen(r, samples[(j + 1) * kAzimuths + k]);
        }
    }
    const Refraction flat = samples[0];
    const double a =
        (in.depth + in.amplitude) * focusing.widened_high() * in.curvature + in.slope * tan_phi.widened_high();
    if (!(a < 1.0)) {
        bound.unbounded_because = focusing_reason(a);
        return bound;
    }
    const double projection = in.slope * std::tan(sun_zenith);
    const double path_change = in.amplitude * inverse_cos_phi.widened_high() +
                               in.depth * std::max(inverse_cos_phi.widened_high() - flat.inverse_cos_phi,
                                                   flat.inverse_cos_phi - inverse_cos_phi.widened_low());
    const double attenuation = std::exp(in.sigma_t * path_change);
    bound.low = (1.0 - projection) * std::max(0.0, transmittance.widened_low()) / flat.transmittance / attenuation /
                ((1.0 + a) * (1.0 + a));
    bound.high =
        (1.0 + projection) * transmittance.widened_high() / flat.transmittance * attenuation / ((1.0 - a) * (1.0 - a));
    if (!(bound.low > 0.0)) {
        bound.unbounded_because = describe("the surface's tilt may block the sun (slope bound %.3g)", in.slope);
        return bound;
    }
    bound.bounded = true;
    return bound;
}

}  // namespace vkw
