// How far the waves can move the sun's irradiance in the water from flat water's: a bound on the
// modulation m = E_h / E_h,flat that docs/model.md section 6 applies to the in-scatter under waves
// (the volume caustics), from the surface's bounds on its height, slope and curvature. The frame's
// needs use it to leave the godray passes out where the shading's flat in-scatter is within a
// display step of what they would add (passes/frame/frame_needs.cpp).
#pragma once

#include <glm/glm.hpp>

#include <string>

namespace vkw {

struct BeamModulationInputs {
    glm::dvec3 sun{0.0, -1.0, 0.0};  // the direction the sunlight travels (unit, y < 0)
    double ior = 1.333;              // the water's n
    double amplitude = 0.0;          // A: |h| <= A about the mean level, m
    double slope = 0.0;              // S: |grad h| <= S
    double curvature = 0.0;          // kappa: |u^T H u| <= kappa for unit horizontal u, 1/m
    double depth = 0.0;              // D: the deepest lit water below the mean level, m
    double sigma_t = 0.0;            // the medium's largest extinction coefficient, 1/m

    bool operator==(const BeamModulationInputs&) const = default;
};

struct BeamModulationBound {
    bool bounded = false;
    double low = 0.0, high = 0.0;   // low <= m <= high everywhere down to the depth D
    std::string unbounded_because;  // when !bounded: why no bound follows from the inputs

    // The largest relative change of an in-scatter integral when m is replaced by 1, over the
    // modulated one: max(high - 1, 1 - low) / low (the modulated integral is at least low times
    // the flat one). Infinity when unbounded.
    double largest_relative_change() const;
};

// Per unit horizontal area of a surface cell at x0, the water below receives
// E_s (-s . N_un) T(theta_i) (N_un = (-h_x, 1, -h_z)), carried along the refracted direction t(x0)
// with attenuation exp(-sigma_t l) to where it crosses the plane at depth z,
// X = x0 + (z + h) t_h / |t_y|; so m = f_proj f_T f_att / |det dX/dx0| against flat water's, with
//   f_proj = (-s . N_un) / (-s_y)            within 1 +- S tan(theta_s)
//   f_T    = T(theta_i) / T(theta_s)         over the normals tilted by up to atan(S)
//   f_att  = exp(-sigma_t (l - l_flat))      |l - l_flat| <= A / cos(phi) + D |1/cos(phi) - 1/cos(theta_t)|
//   dX/dx0 = I + (z + h) d(t_h / |t_y|)/dx0 + grad h (x) t_h / |t_y|, whose distance from I is at most
//            a = (D + A) K kappa + S tan(phi)_max, K = (n cos t - cos i) / (n cos t cos^2 phi) the
//            rate at which the tangent of the refracted ray's angle phi from the vertical turns
//            with the normal's tilt in the plane of incidence (the larger of the two principal
//            rates), so (1 - a)^2 <= |det| <= (1 + a)^2 while a < 1 (and the map from x0 to X is
//            one to one: no caustic forms above the depth D).
// theta_i, phi and K are taken over the normals whose tilt is at most atan(S), sampled on a grid of
// tilts and azimuths, each extreme widened by the largest change between neighbouring samples.
// Unbounded where S or kappa is infinite, the sun may graze the tilted surface, or a >= 1.
BeamModulationBound beam_modulation_bound(const BeamModulationInputs& inputs);

}  // namespace vkw
