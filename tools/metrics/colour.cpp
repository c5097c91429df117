// Colorimetry: the sRGB matrix from its chromaticities, CIE L*a*b* and L*u*v*.
#include "tools/metrics/colour.hpp"

#include <cmath>

namespace vkw::metrics {
namespace {

Vec3 multiply(const Mat3& m, const Vec3& v) {
    return {m[0][0] * v[0] + m[0][1] * v[1] + m[0][2] * v[2], m[1][0] * v[0] + m[1][1] * v[1] + m[1][2] * v[2],
            m[2][0] * v[0] + m[2][1] * v[1] + m[2][2] * v[2]};
}

Mat3 inverse(const Mat3& m) {
    // Adjugate over determinant; the matrices here are well conditioned.
    const double det = m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1]) -
                       m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0]) +
                       m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0]);
    Mat3 r{};
    r[0][0] = (m[1][1] * m[2][2] - m[1][2] * m[2][1]) / det;
    r[0][1] = (m[0][2] * m[2][1] - m[0][1] * m[2][2]) / det;
    r[0][2] = (m[0][1] * m[1][2] - m[0][2] * m[1][1]) / det;
    r[1][0] = (m[1][2] * m[2][0] - m[1][0] * m[2][2]) / det;
    r[1][1] = (m[0][0] * m[2][2] - m[0][2] * m[2][0]) / det;
    r[1][2] = (m[0][2] * m[1][0] - m[0][0] * m[1][2]) / det;
    r[2][0] = (m[1][0] * m[2][1] - m[1][1] * m[2][0]) / det;
    r[2][1] = (m[0][1] * m[2][0] - m[0][0] * m[2][1]) / det;
    r[2][2] = (m[0][0] * m[1][1] - m[0][1] * m[1][0]) / det;
    return r;
}

// XYZ with Y = 1 of chromaticity (x, y).
Vec3 xyz_of_chromaticity(double x, double y) { return {x / y, 1.0, (1.0 - x - y) / y}; }

Mat3 derive_srgb_to_xyz() {
    const Vec3 r = xyz_of_chromaticity(0.64, 0.33);
    const Vec3 g = xyz_of_chromaticity(0.30, 0.60);
    const Vec3 b = xyz_of_chromaticity(0.15, 0.06);
    const Mat3 primaries{{{r[0], g[0], b[0]}, {r[1], g[1], b[1]}, {r[2], g[2], b[2]}}};
    // Scale each primary so that together they make the white: primaries * s = white.
    const Vec3 s = multiply(inverse(primaries), xyz_of_chromaticity(0.3127, 0.3290));
    Mat3 m{};
    for (int row = 0; row < 3; ++row) {
        for (int col = 0; col < 3; ++col) m[row][col] = primaries[row][col] * s[col];
    }
    return m;
}

// The CIE's cube root with its linear segment near black.
double cie_f(double t) {
    constexpr double delta = 6.0 / 29.0;
    return t > delta * delta * delta ? std::cbrt(t) : t / (3.0 * delta * delta) + 4.0 / 29.0;
}

// CIE 1976 u'v' chromaticity.
std::array<double, 2> uv_prime(const Vec3& xyz) {
    const double d = xyz[0] + 15.0 * xyz[1] + 3.0 * xyz[2];
    return {4.0 * xyz[0] / d, 9.0 * xyz[1] / d};
}

}  // namespace

const Mat3& srgb_to_xyz_matrix() {
    static const Mat3 m = derive_srgb_to_xyz();
    return m;
}

const Mat3& xyz_to_srgb_matrix() {
    static const Mat3 m = inverse(srgb_to_xyz_matrix());
    return m;
}

Vec3 linear_srgb_to_xyz(const Vec3& rgb) { return multiply(srgb_to_xyz_matrix(), rgb); }
Vec3 xyz_to_linear_srgb(const Vec3& xyz) { return multiply(xyz_to_srgb_matrix(), xyz); }

const Vec3& d65_white() {
    static const Vec3 white = linear_srgb_to_xyz({1.0, 1.0, 1.0});
    return white;
}

double luminance(const Vec3& rgb) {
    const Vec3& y = srgb_to_xyz_matrix()[1];
    return y[0] * rgb[0] + y[1] * rgb[1] + y[2] * rgb[2];
}

double cie_lightness(double relative_luminance) { return 116.0 * cie_f(relative_luminance) - 16.0; }

Vec3 xyz_to_lab(const Vec3& xyz) {
    const Vec3& w = d65_white();
    const double fx = cie_f(xyz[0] / w[0]);
    const double fy = cie_f(xyz[1] / w[1]);
    const double fz = cie_f(xyz[2] / w[2]);
    return {116.0 * fy - 16.0, 500.0 * (fx - fy), 200.0 * (fy - fz)};
}

Vec3 xyz_to_luv(const Vec3& xyz) {
    const Vec3& w = d65_white();
    const double l = cie_lightness(xyz[1] / w[1]);
    const std::array<double, 2> white_uv = uv_prime(w);
    if (xyz[0] + 15.0 * xyz[1] + 3.0 * xyz[2] <= 0.0) return {l, 0.0, 0.0};
    const std::array<double, 2> uv = uv_prime(xyz);
    return {l, 13.0 * l * (uv[0] - white_uv[0]), 13.0 * l * (uv[1] - white_uv[1])};
}

}  // namespace vkw::metrics
