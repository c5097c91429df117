// docs/model.md section 5's sine profile by an independent method (no beams): shared by the
// floor-map test and the in-scatter test (the irradiance on a plane at any depth).
#pragma once

#include "tools/reference/optics.hpp"

#include <glm/glm.hpp>

#include <cmath>
#include <vector>

namespace vkw::ref {

// docs/model.md section 5, h = A sin(kx), vertical sun: the texel-averaged floor irradiance,
// computed here by an independent method: the exact 1-D map X(x) = x + (d + h) t_x / (-t_y)
// sampled at 2^22 points per metre, each carrying its flux E_s T exp(-sigma_t l) dx into the
// texel of its landing point (a histogram of the map, converging as dx -> 0).
inline std::vector<double> sine_profile(double amplitude, double k, double depth, double sigma_t, double extent,
                                        double floor_extent, int texels, double ior) {
    std::vector<double> flux(texels, 0.0);
    const double texel = 2.0 * floor_extent / texels;
    const int samples = static_cast<int>(2.0 * extent * (1 << 22));
    const double dx = 2.0 * extent / samples;
    for (int i = 0; i < samples; ++i) {
        const double x = -extent + (i + 0.5) * dx;
        const double slope = amplitude * k * std::cos(k * x);
        const double h = amplitude * std::sin(k * x);
        const glm::dvec3 normal = glm::normalize(glm::dvec3(-slope, 1.0, 0.0));
        const glm::dvec3 t = *refract({0.0, -1.0, 0.0}, normal, 1.0 / ior);
        const double path = (depth + h) / -t.y;
        const double landing = x + path * t.x;
        const double transmittance = 1.0 - fresnel_reflectance(normal.y, 1.0, ior);
        const int bin = static_cast<int>(std::floor((landing + floor_extent) / texel));
        if (bin >= 0 && bin < texels) flux[bin] += transmittance * std::exp(-sigma_t * path) * dx;
    }
    for (double& f : flux) f /= texel;  // E_s = 1
    return flux;
}

}  // namespace vkw::ref
