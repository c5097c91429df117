// The unpolarised Fresnel reflectance in double precision, in the angle form of the equations
// (not the cosine form shaders/common/fresnel.glsl uses): an independent check of the shaders.
#pragma once

#include <algorithm>
#include <cmath>

namespace vkw::test {

// r_s = -sin(i - t) / sin(i + t), r_p = tan(i - t) / tan(i + t); the limit at normal incidence is
// ((n1 - n2)/(n1 + n2))^2.
inline double reflectance(double cos_i, double n_i, double n_t) {
    const double sin_i = std::sqrt(std::max(0.0, 1.0 - cos_i * cos_i));
    const double sin_t = n_i / n_t * sin_i;
    if (sin_t >= 1.0) return 1.0;
    if (sin_i < 1e-9) return std::pow((n_i - n_t) / (n_i + n_t), 2);
    const double i = std::asin(sin_i), t = std::asin(sin_t);
    if (cos_i == 0.0) return 1.0;  // grazing: both amplitudes are -1 (tan(i + t) is infinite)
    const double rs = -std::sin(i - t) / std::sin(i + t);
    const double rp = std::tan(i - t) / std::tan(i + t);
    return 0.5 * (rs * rs + rp * rp);
}

}  // namespace vkw::test
