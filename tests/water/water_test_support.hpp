// Shared checks of the water tests: analytic tangents and normals against central
// differences of the positions, with the tolerance derived from the step.
#pragma once

#include <cmath>
#include <limits>

#include <gtest/gtest.h>
#include <glm/glm.hpp>

#include "engine/water/surface.hpp"

namespace vkw::test {

// (P(u + h) - P(u - h)) / (2h) = P'(u) + h^2 / 6 P'''(xi): the truncation error is at most
// h^2 / 6 times a bound on |P'''| (for a wave, k^3 times its amplitude). Each P also carries a
// rounding error of a few eps times the magnitude `scale` of the sums that make it (the
// coordinate, the level and the wave terms, sin() of a phase k x adding eps k x A), and the
// difference divides that by 2h: 16 eps scale / h is a generous bound.
inline double central_difference_tolerance(double step, double third_derivative_bound, double scale) {
    return step * step / 6.0 * third_derivative_bound + 16.0 * std::numeric_limits<double>::epsilon() * scale / step;
}

// Checks dP_du, dP_dv and the normal at (x0, z0) against central differences with step h.
inline void expect_derivatives_match_differences(const WaterSurface& surface, double x0, double z0, double step,
                                                 double tolerance) {
    const SurfacePoint p = surface.at_parameter(x0, z0);
    const glm::dvec3 du =
        (surface.at_parameter(x0 + step, z0).position - surface.at_parameter(x0 - step, z0).position) / (2.0 * step);
    const glm::dvec3 dv =
        (surface.at_parameter(x0, z0 + step).position - surface.at_parameter(x0, z0 - step).position) / (2.0 * step);
    for (int c = 0; c < 3; ++c) {
        EXPECT_NEAR(p.dP_du[c], du[c], tolerance) << "dP_du[" << c << "] at " << x0 << ", " << z0;
        EXPECT_NEAR(p.dP_dv[c], dv[c], tolerance) << "dP_dv[" << c << "] at " << x0 << ", " << z0;
    }
    // The normal from the differenced tangents: the tangent errors enter the cross product
    // once per factor, and normalising divides by |cross| (>= 0.1 on the surfaces tested), so
    // 4 |tangent| / |cross| times the tangent tolerance bounds its error.
    const glm::dvec3 cross = glm::cross(dv, du);
    const double normal_tolerance = 4.0 * tolerance * (glm::length(du) + glm::length(dv)) / glm::length(cross);
    const glm::dvec3 n = glm::normalize(cross);
    EXPECT_NEAR(glm::length(p.normal), 1.0, 1e-14);
    EXPECT_GT(p.normal.y, 0.0);
    for (int c = 0; c < 3; ++c) {
        EXPECT_NEAR(p.normal[c], n[c], normal_tolerance) << "normal[" << c << "]";
    }
}

}  // namespace vkw::test
