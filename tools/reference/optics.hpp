// The optics of the light-transport model (docs/model.md sections 1-3 and 6) in double
// precision, for the CPU reference renderer and as the expected values of the
// shader tests. Written independently of the GLSL in shaders/common/: nothing is
// shared between the two but the equations.
#pragma once

#include <glm/glm.hpp>

#include <optional>

namespace vkw::ref {

// Unpolarised dielectric reflectance for a ray arriving at cosine cos_i from the
// medium of index n_i into n_t; 1 under total internal reflection.
double fresnel_reflectance(double cos_i, double n_i, double n_t);

// Cosine of the refraction angle, or nothing under total internal reflection.
std::optional<double> refracted_cosine(double cos_i, double n_i, double n_t);

// Refracts unit direction `incident` at unit normal `normal` (on the incident side),
// eta = n_i / n_t; nothing under total internal reflection.
std::optional<glm::dvec3> refract(const glm::dvec3& incident, const glm::dvec3& normal, double eta);

// Henyey-Greenstein phase function, per steradian: (1 - g^2) / (4 pi (1 + g^2 - 2 g cos a)^1.5).
double henyey_greenstein(double cos_angle, double g);

// (1 - exp(-x)) / x, valid for any x including x <= 0, tending to 1 at x = 0.
double one_minus_exp_over_x(double x);

// T_hemi(n) = 2 * integral_0^{pi/2} T(theta) cos(theta) sin(theta) d(theta), air to water.
double hemispherical_transmittance(double ior);

// docs/model.md section 6 for one channel: radiance in the water along a view ray that
// starts (or enters) at depth z0 >= 0 and runs a length s in unit direction v, with
// the sun's refracted beam t (unit, downward) of irradiance e_perp0 on a plane normal
// to it just below the surface (E_s T cos(theta_s) / cos(theta_t)).
struct InScatterInput {
    double sigma_s, sigma_t, g;
    double z0, s;
    glm::dvec3 view_direction;  // v, unit
    glm::dvec3 refracted_sun;   // t, unit, t.y < 0
    double e_perp0;
    double l_behind;  // radiance at the far end of the segment
};
double water_path_radiance(const InScatterInput& in);

}  // namespace vkw::ref
