// The glitter lobes' expected fluxes in double precision, independently of the shaders: the flux a
// Gaussian distribution of facets reflects or transmits from a directional source, integrated over
// the slopes (tests/optics/glitter_test.cpp checks the lobes against it; tests/render's glitter frame
// test, a whole frame).
#pragma once

#include "tests/optics/fresnel_angle_form.hpp"

#include <glm/glm.hpp>

#include <cmath>
#include <numbers>

namespace vkw::test {

// The water of the glitter tests.
constexpr double kGlitterIor = 1.333;

inline glm::dvec3 direction(double elevation_deg, double azimuth_deg) {
    const double e = elevation_deg * std::numbers::pi / 180.0, a = azimuth_deg * std::numbers::pi / 180.0;
    return {std::cos(e) * std::sin(a), std::sin(e), -std::cos(e) * std::cos(a)};
}

inline glm::dvec3 normal_of_slope(const glm::dvec2& z) { return glm::normalize(glm::dvec3(-z.x, 1.0, -z.y)); }

// The direction of the light from l (toward the source, in the air) refracted through a facet of
// normal h into water of index n, by Snell's law in vector form.
inline glm::dvec3 refracted(const glm::dvec3& l, const glm::dvec3& h, double n) {
    const double cos_i = glm::dot(l, h);
    const double cos_t = std::sqrt(1.0 - (1.0 - cos_i * cos_i) / (n * n));
    return -l / n + (cos_i / n - cos_t) * h;
}

enum class Lobe { Reflected, Transmitted };

// The flux the facets send on per unit source irradiance: the integral over slopes z of
// F(l.h) (l.h) / h_y p(z) (reflected, over the slopes whose mirror sends l upward) or
// T(l.h) (l.h) / h_y p(z) (transmitted, over those whose refraction sends it down), p Gaussian of
// mean `mean` and covariance (S_xx, S_xz, S_zz), by the midpoint rule over +-9 standard deviations of
// each axis in 1201^2 cells (cells of 0.015 sigma: the rule's error on a Gaussian is below 1e-6).
inline double facet_flux(const glm::dvec3& l, const glm::dvec2& mean, const glm::dvec3& s,
                         Lobe lobe = Lobe::Reflected) {
    const double sx = std::sqrt(s.x), sz = std::sqrt(s.z), det = s.x * s.z - s.y * s.y;
    const int cells = 1201;
    const double dx = 18.0 * sx / cells, dz = 18.0 * sz / cells;
    double flux = 0.0;
    for (int i = 0; i < cells; ++i) {
        for (int j = 0; j < cells; ++j) {
            const glm::dvec2 d(-9.0 * sx + (i + 0.5) * dx, -9.0 * sz + (j + 0.5) * dz);
            const glm::dvec3 h = normal_of_slope(mean + d);
            const double lh = glm::dot(l, h);
            if (!(lh > 0.0)) continue;
            const bool transmitted = lobe == Lobe::Transmitted;
            if (transmitted ? !(refracted(l, h, kGlitterIor).y < 0.0) : !((2.0 * lh * h - l).y > 0.0)) continue;
            const double q = (s.z * d.x * d.x - 2.0 * s.y * d.x * d.y + s.x * d.y * d.y) / det;
            const double density = std::exp(-0.5 * q) / (2.0 * std::numbers::pi * std::sqrt(det));
            const double f = reflectance(lh, 1.0, kGlitterIor);
            flux += (transmitted ? 1.0 - f : f) * lh / h.y * density * dx * dz;
        }
    }
    return flux;
}

}  // namespace vkw::test
