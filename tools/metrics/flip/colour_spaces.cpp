// YCxCz, Hunt-adjusted L*a*b*, HyAB and the redistribution of FLIP's colour error.
#include "tools/metrics/flip/colour_spaces.hpp"

#include <algorithm>
#include <cmath>

namespace vkw::metrics::flip {
namespace {

constexpr double kQc = 0.7;   // colour exponent
constexpr double kPc = 0.4;   // fraction of c_max mapped onto [0, pt]
constexpr double kPt = 0.95;  // the error those differences reach

double max_colour_distance() {
    static const double c_max =
        std::pow(hyab(hunt_adjusted_lab({0.0, 1.0, 0.0}), hunt_adjusted_lab({0.0, 0.0, 1.0})), kQc);
    return c_max;
}

}  // namespace

Vec3 linear_rgb_to_ycxcz(const Vec3& rgb) {
    const Vec3 xyz = linear_srgb_to_xyz(rgb);
    const Vec3& w = d65_white();
    const double x = xyz[0] / w[0], y = xyz[1] / w[1], z = xyz[2] / w[2];
    return {116.0 * y - 16.0, 500.0 * (x - y), 200.0 * (y - z)};
}

Vec3 ycxcz_to_linear_rgb(const Vec3& ycxcz) {
    const Vec3& w = d65_white();
    const double y = (ycxcz[0] + 16.0) / 116.0;
    const double x = y + ycxcz[1] / 500.0;
    const double z = y - ycxcz[2] / 200.0;
    return xyz_to_linear_srgb({x * w[0], y * w[1], z * w[2]});
}

Vec3 hunt_adjusted_lab(const Vec3& linear_rgb) {
    Vec3 clamped{};
    for (int c = 0; c < 3; ++c) clamped[c] = std::clamp(linear_rgb[c], 0.0, 1.0);
    const Vec3 lab = xyz_to_lab(linear_srgb_to_xyz(clamped));
    return {lab[0], 0.01 * lab[0] * lab[1], 0.01 * lab[0] * lab[2]};
}

double hyab(const Vec3& lab_a, const Vec3& lab_b) {
    return std::abs(lab_a[0] - lab_b[0]) + std::hypot(lab_a[1] - lab_b[1], lab_a[2] - lab_b[2]);
}

double colour_error(double hyab_distance) {
    const double d = std::pow(hyab_distance, kQc);
    const double c_max = max_colour_distance();
    const double knee = kPc * c_max;
    if (d < knee) return d * kPt / knee;
    return kPt + (d - knee) / (c_max - knee) * (1.0 - kPt);
}

}  // namespace vkw::metrics::flip
