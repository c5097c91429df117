// Colorimetry shared by the L*u*v* metric and FLIP: linear sRGB <-> CIE XYZ (D65), luminance,
// CIE 1976 L*a*b* and L*u*v*.
#pragma once

#include <array>

namespace vkw::metrics {

using Vec3 = std::array<double, 3>;
using Mat3 = std::array<Vec3, 3>;  // row-major

// The linear-sRGB -> XYZ matrix, derived (not typed in) from the sRGB primaries' chromaticities
// R (0.64, 0.33), G (0.30, 0.60), B (0.15, 0.06) and the D65 white (0.3127, 0.3290) of
// IEC 61966-2-1, scaled so RGB (1, 1, 1) has Y = 1. Its Y row is the luminance weights
// (0.212639, 0.715169, 0.072192): Rec. 709's rounded 0.2126, 0.7152, 0.0722 to 4 decimals.
const Mat3& srgb_to_xyz_matrix();
const Mat3& xyz_to_srgb_matrix();

Vec3 linear_srgb_to_xyz(const Vec3& rgb);
Vec3 xyz_to_linear_srgb(const Vec3& xyz);

// XYZ of RGB (1, 1, 1): the D65 white with Y = 1, the reference white of both CIE spaces below.
const Vec3& d65_white();

// Relative luminance Y of a linear sRGB colour.
double luminance(const Vec3& rgb);

// CIE 1976 lightness L* of relative luminance Y / Yn: 116 (Y/Yn)^(1/3) - 16 above
// (6/29)^3, (29/3)^3 Y/Yn below.
double cie_lightness(double relative_luminance);

// CIE 1976 L*a*b* and L*u*v* of XYZ, reference white d65_white(). A black colour
// (X + 15Y + 3Z = 0) gets the white's u'v', so its u* = v* = 0 like its L*.
Vec3 xyz_to_lab(const Vec3& xyz);
Vec3 xyz_to_luv(const Vec3& xyz);

}  // namespace vkw::metrics
