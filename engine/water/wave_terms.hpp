// The per-wave constants of a sum of sine and Gerstner waves at one time, in double: the one
// place their formulas live, shared by the CPU surface (WaveSumSurface) and the GPU wave-sum
// pass (passes/water/water_surface_sum.cpp, which rounds them to fp32). The wave model and its
// symbols are those of wave_sum_surface.hpp:
//   theta = k_vector . (x0, z0) + phase_at_origin
//   h     = sum amplitude sin(theta)
//   D     = sum displacement_scale k_vector cos(theta)
#pragma once

#include <glm/glm.hpp>

#include "engine/water/wave_params.hpp"

namespace vkw {

struct WaveTerms {
    glm::dvec2 k_vector;        // k d, rad/m (k = 2 pi / wavelength, d the unit direction of travel)
    double phase_at_origin;     // -w t + p, radians (w = k speed, or sqrt(g k) for speed < 0); not reduced
    double amplitude;           // A, m
    double displacement_scale;  // s / k^2, so that D = displacement_scale k_vector cos(theta)
};

// The constants of component `c` at `time` seconds. No validation: validate_waves first.
WaveTerms wave_terms(const WaveComponent& c, double time);

}  // namespace vkw
