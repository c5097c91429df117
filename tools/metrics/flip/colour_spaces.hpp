// FLIP's colour spaces and colour difference (FLIP paper, Andersson et al. 2020, colour
// pipeline): the opponent space YCxCz the CSFs filter in, the Hunt-adjusted L*a*b* the
// difference is measured in, the HyAB distance and its mapping to [0, 1].
#pragma once

#include "tools/metrics/colour.hpp"

namespace vkw::metrics::flip {

// YCxCz (a linearised L*a*b*, so that filtering is linear): from XYZ relative to the D65
// white (Xn, Yn, Zn) = d65_white(),
//   Y' = 116 Y/Yn - 16,  Cx = 500 (X/Xn - Y/Yn),  Cz = 200 (Y/Yn - Z/Zn).
Vec3 linear_rgb_to_ycxcz(const Vec3& rgb);
Vec3 ycxcz_to_linear_rgb(const Vec3& ycxcz);

// The achromatic feature input: (Y' + 16) / 116 = Y / Yn, the relative luminance.
inline double normalised_achromatic(double y_prime) { return (y_prime + 16.0) / 116.0; }

// Hunt adjustment of CIE L*a*b* (colourfulness grows with luminance): (L, 0.01 L a, 0.01 L b).
// Takes linear RGB, clamped to [0, 1] first (the paper clamps the filtered colour to the RGB
// cube before the perceptual transform).
Vec3 hunt_adjusted_lab(const Vec3& linear_rgb);

// HyAB distance (Abasi et al. 2020): |dL| + sqrt(da^2 + db^2).
double hyab(const Vec3& lab_a, const Vec3& lab_b);

// The colour error Delta E_c in [0, 1] of a HyAB distance between Hunt-adjusted colours:
//   d = hyab^qc, qc = 0.7 (compresses large differences);
//   c_max = hyab(Hunt(green), Hunt(blue))^qc, the largest distance between two colours of the
//           RGB cube (green (0, 1, 0) and blue (0, 0, 1));
//   the first pc = 0.4 of [0, c_max] maps linearly onto [0, pt = 0.95], the rest onto
//   [pt, 1], so the many small differences spread over most of the range:
//   d < pc c_max:  d pt / (pc c_max);  else:  pt + (d - pc c_max) / (c_max - pc c_max) (1 - pt).
double colour_error(double hyab_distance);

}  // namespace vkw::metrics::flip
