// docs/model.md section 4's flux through the surface onto the floor, computed independently of
// the beams (midpoint quadrature over the surface's parameter square, not their own sum):
//   Phi = E_s * integral of max(0, -s . (dP/dz0 x dP/dx0)) T(theta_i) exp(-sigma_t l) dx0 dz0,
// where dP/dz0 x dP/dx0 is the upward normal scaled by the surface's area per parameter area;
// for a heightfield it is (-h_x, 1, -h_z), and -s . it = cos(theta_s) - u_h . grad h, the
// section's integrand. Shared by the floor-map tests of sums of sines and of the FFT ocean.
#pragma once

#include "engine/scene/scene.hpp"
#include "engine/water/surface.hpp"
#include "tools/reference/optics.hpp"

#include <glm/glm.hpp>

#include <algorithm>
#include <cmath>

namespace vkw::ref {

// Over the parameter square [lo, lo + side]^2 with steps x steps midpoints.
inline glm::dvec3 section4_flux(const Scene& scene, const WaterSurface& surface, double lo, double side, int steps) {
    const glm::dvec3 s = scene.sun.direction;
    const double ior = scene.water->ior;
    const double cell = side / steps;
    const glm::dvec3 sigma_t = scene.medium.sigma_t();
    glm::dvec3 flux(0.0);
    for (int j = 0; j < steps; ++j) {
        for (int i = 0; i < steps; ++i) {
            const SurfacePoint p = surface.at_parameter(lo + (i + 0.5) * cell, lo + (j + 0.5) * cell);
            const double projected = std::max(0.0, -glm::dot(s, glm::cross(p.dP_dv, p.dP_du)));
            const double cos_i = -glm::dot(s, p.normal);
            if (projected <= 0.0 || cos_i <= 0.0) continue;
            const glm::dvec3 t = *refract(s, p.normal, 1.0 / ior);
            const double path = (p.position.y - scene.floor.height) / -t.y;
            const double transmittance = 1.0 - fresnel_reflectance(cos_i, 1.0, ior);
            flux += scene.sun.irradiance * (projected * transmittance * cell * cell) *
                    glm::dvec3(std::exp(-sigma_t.x * path), std::exp(-sigma_t.y * path), std::exp(-sigma_t.z * path));
        }
    }
    return flux;
}

}  // namespace vkw::ref
