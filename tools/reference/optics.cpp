#include "tools/reference/optics.hpp"

#include <cmath>
#include <numbers>

namespace vkw::ref {

std::optional<double> refracted_cosine(double cos_i, double n_i, double n_t) {
    const double sin2_t = (n_i / n_t) * (n_i / n_t) * (1.0 - cos_i * cos_i);
    if (sin2_t >= 1.0) return std::nullopt;
    return std::sqrt(1.0 - sin2_t);
}

double fresnel_reflectance(double cos_i, double n_i, double n_t) {
    const auto cos_t = refracted_cosine(cos_i, n_i, n_t);
    if (!cos_t) return 1.0;
    const double rs = (n_i * cos_i - n_t * *cos_t) / (n_i * cos_i + n_t * *cos_t);
    const double rp = (n_t * cos_i - n_i * *cos_t) / (n_t * cos_i + n_i * *cos_t);
    return 0.5 * (rs * rs + rp * rp);
}

std::optional<glm::dvec3> refract(const glm::dvec3& incident, const glm::dvec3& normal, double eta) {
    const double cos_i = -glm::dot(incident, normal);
    const double k = 1.0 - eta * eta * (1.0 - cos_i * cos_i);
    if (k < 0.0) return std::nullopt;
    return glm::normalize(eta * incident + (eta * cos_i - std::sqrt(k)) * normal);
}

double henyey_greenstein(double cos_angle, double g) {
    const double denominator = 1.0 + g * g - 2.0 * g * cos_angle;
    return (1.0 - g * g) / (4.0 * std::numbers::pi * denominator * std::sqrt(denominator));
}

double one_minus_exp_over_x(double x) { return x == 0.0 ? 1.0 : -std::expm1(-x) / x; }

double hemispherical_transmittance(double ior) {
    // Gauss-Legendre would do; a fine midpoint rule in double is exact to ~1e-9 here.
    const int steps = 200000;
    double sum = 0.0;
    for (int i = 0; i < steps; ++i) {
        const double theta = (i + 0.5) / steps * (std::numbers::pi / 2);
        const double c = std::cos(theta);
        sum += (1.0 - fresnel_reflectance(c, 1.0, ior)) * c * std::sin(theta);
    }
    return 2.0 * sum * (std::numbers::pi / 2) / steps;
}

double water_path_radiance(const InScatterInput& in) {
    const double cos_t = -in.refracted_sun.y;       // cos(theta_t)
    const double c = -in.view_direction.y / cos_t;  // downward component of v over cos(theta_t)
    const double cos_alpha = glm::dot(in.refracted_sun, -in.view_direction);
    // exp(-tau0) (1 - exp(-x)) / x with tau0 the sun's optical depth at z0 and
    // x = sigma_t s (1 + c). For x < 0 (rays rising faster than the beam sinks) it is
    // rewritten as exp(-(tau0 + x)) (1 - exp(x)) / (-x): tau0 + x is the optical depth
    // at the segment's shallow end, >= 0, so neither exponential can overflow.
    const double tau0 = in.sigma_t * in.z0 / cos_t;
    const double x = in.sigma_t * in.s * (1.0 + c);
    const double beam =
        x >= 0.0 ? std::exp(-tau0) * one_minus_exp_over_x(x) : std::exp(-(tau0 + x)) * one_minus_exp_over_x(-x);
    const double scattered = in.sigma_s * henyey_greenstein(cos_alpha, in.g) * in.e_perp0 * in.s * beam;
    return in.l_behind * std::exp(-in.sigma_t * in.s) + scattered;
}

}  // namespace vkw::ref
