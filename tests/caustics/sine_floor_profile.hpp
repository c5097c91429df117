// The floor irradiance under a sine surface h = A sin(k x + phase) lit by a vertical sun,
// docs/model.md section 5 evaluated on the CPU in double precision, independently of the photon code
// (no engine or pass code: only the formulas of docs/model.md sections 2 and 5), and filtered per
// texel of a caustic map row:
// - Box: the texel average (1/h) * integral over the texel of E(X) dX, the quantity the 2% bound is stated for;
// - Tent: (1/h) * integral of E(X) tent((X - c)/h) dX, tent(u) = max(0, 1 - |u|), c the texel
//   centre: what a map built by bilinear (2x2) splatting tends to as the photons get denser,
//   since each photon adds its flux times tent((X_j - c)/h) to the texel.
// How: the surface [x0, x1] is cut into segments; each carries its flux per unit length along z,
// E_s T(theta_i) exp(-sigma_t l) dx at its midpoint (the vertical sun meets a strip dx wide
// over dx: no slope factor), to its footprint [X(x_a), X(x_b)] on the floor, spread uniformly
// there and filtered exactly. Error of this evaluation: a segment's flux is misplaced by at most
// its footprint's width (at most 3 dx wherever |X'| <= 3), so with 2^16 segments per wavelength
// a texel of lambda/64 takes a fraction ~ 3/1024 of one segment's flux from its neighbour per
// edge: below 1e-5 of its value (a segment across a fold turns back within its own few dx, so
// the same holds there); the midpoint flux is off by O(dx^2) ~ 1e-9.
#pragma once

#include <glm/glm.hpp>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

namespace vkw::test {

struct SineFloor {
    double amplitude = 0.0;   // A, m
    double wavenumber = 1.0;  // k, 1/m
    double phase = 0.0;       // radians: h = A sin(k x + phase)
    double ior = 1.333;       // n
    double depth = 1.0;       // d: the floor lies at y = -d, the mean level at y = 0
    glm::dvec3 sun_irradiance{1.0};
    glm::dvec3 sigma_t{0.0};

    double height(double x) const { return amplitude * std::sin(wavenumber * x + phase); }
    double slope(double x) const { return amplitude * wavenumber * std::cos(wavenumber * x + phase); }

    // docs/model.md section 5: f = 1 / ((1 - 1/n) A k^2) and the first cusp's depth d* = f - A.
    double focal_length() const { return 1.0 / ((1.0 - 1.0 / ior) * amplitude * wavenumber * wavenumber); }
    double first_cusp_depth() const { return focal_length() - amplitude; }

    // Before the focus, the crest's irradiance E_s T(0) exp(-sigma_t (d + A)) / (1 - (d + A) / f).
    glm::dvec3 crest_closed_form() const {
        const double t0 = 4.0 * ior / ((ior + 1.0) * (ior + 1.0));
        const double path = depth + amplitude;
        return sun_irradiance * t0 * glm::exp(-sigma_t * path) / (1.0 - path / focal_length());
    }

    // The refracted beam leaving the surface point at x: where it meets the floor, its path in the
    // water and the Fresnel transmittance, exact (not small-slope).
    struct Beam {
        double floor_x, path, transmittance;
    };
    Beam beam(double x) const {
        const double hp = slope(x);
        const double norm = std::sqrt(1.0 + hp * hp);
        const glm::dvec2 normal(-hp / norm, 1.0 / norm), incident(0.0, -1.0);
        const double eta = 1.0 / ior, cos_i = 1.0 / norm;
        const double cos_t = std::sqrt(1.0 - eta * eta * (1.0 - cos_i * cos_i));
        const glm::dvec2 t = eta * incident + (eta * cos_i - cos_t) * normal;
        const double rs = (cos_i - ior * cos_t) / (cos_i + ior * cos_t);
        const double rp = (ior * cos_i - cos_t) / (ior * cos_i + cos_t);
        const double drop = depth + height(x);
        return {x + drop * t.x / -t.y, drop / -t.y, 1.0 - 0.5 * (rs * rs + rp * rp)};
    }

    // Over one wavelength: the largest |X'(x)| (how far apart the floor spreads surface points)
    // and the largest sideways travel |X(x) - x|, by sampling 4096 points.
    double max_stretch() const {
        double most = 0.0;
        for (int s = 0; s < 4096; ++s) {
            const double x = 2.0 * std::numbers::pi / wavenumber * s / 4096.0, e = 1e-7;
            most = std::max(most, std::abs(beam(x + e).floor_x - beam(x - e).floor_x) / (2.0 * e));
        }
        return most;
    }
    double max_reach() const {
        double most = 0.0;
        for (int s = 0; s < 4096; ++s) {
            const double x = 2.0 * std::numbers::pi / wavenumber * s / 4096.0;
            most = std::max(most, std::abs(beam(x).floor_x - x));
        }
        return most;
    }
    // The largest flux per unit horizontal area just above the floor, E_s T exp(-sigma_t l), per channel.
    glm::dvec3 max_flux_density() const {
        glm::dvec3 most(0.0);
        for (int s = 0; s < 4096; ++s) {
            const Beam b = beam(2.0 * std::numbers::pi / wavenumber * s / 4096.0);
            most = glm::max(most, sun_irradiance * b.transmittance * glm::exp(-sigma_t * b.path));
        }
        return most;
    }
    // How far a photon's floor point can move when the real-time surface interpolates its normals
    // linearly between vertices `cell` apart. The normal's angle theta(x) = atan(h'(x)) then errs
    // by at most cell^2 / 8 max|theta''| (normalising the interpolated unit vectors adds only
    // O((cell theta')^3)); the floor point moves by (d + A) times the largest change of the
    // refracted beam's sideways drift t_x / -t_y over that angle. Both maxima by sampling one
    // wavelength at 4096 points.
    double interpolated_normal_shift(double cell) const {
        const double wavelength = 2.0 * std::numbers::pi / wavenumber, e = wavelength / 4096.0;
        auto angle = [&](double x) { return std::atan(slope(x)); };
        double curvature = 0.0;
        for (int s = 0; s < 4096; ++s) {
            const double x = wavelength * s / 4096.0;
            curvature = std::max(curvature, std::abs(angle(x + e) - 2.0 * angle(x) + angle(x - e)) / (e * e));
        }
        const double error = cell * cell / 8.0 * curvature;
        double drift_change = 0.0;
        for (int s = 0; s < 4096; ++s) {
            const double theta = angle(wavelength * s / 4096.0);
            drift_change = std::max({drift_change, std::abs(drift(theta + error) - drift(theta)),
                                     std::abs(drift(theta - error) - drift(theta))});
        }
        return (depth + amplitude) * drift_change;
    }

    // t_x / -t_y of the refracted vertical sun through a surface whose normal leans by `angle`.
    double drift(double angle) const {
        const glm::dvec2 normal(-std::sin(angle), std::cos(angle)), incident(0.0, -1.0);
        const double eta = 1.0 / ior, cos_i = normal.y;
        const double cos_t = std::sqrt(1.0 - eta * eta * (1.0 - cos_i * cos_i));
        const glm::dvec2 t = eta * incident + (eta * cos_i - cos_t) * normal;
        return t.x / -t.y;
    }

    // Pointwise E(X) at the floor point under the surface point x, from that branch alone.
    glm::dvec3 branch_irradiance(double x) const {
        const double dx = 1e-6 / wavenumber;
        const double derivative = (beam(x + dx).floor_x - beam(x - dx).floor_x) / (2.0 * dx);
        const Beam b = beam(x);
        return sun_irradiance * b.transmittance * glm::exp(-sigma_t * b.path) / std::abs(derivative);
    }
};

enum class TexelFilter { Box, Tent };

// A row of `count` texels of width h from `corner` on (texel i spans [corner + i h, corner + (i + 1) h]):
// the irradiance of the light from the surface [x0, x1], filtered per texel, W m^-2 per channel.
inline std::vector<glm::dvec3> sine_floor_profile(const SineFloor& sine, double x0, double x1, double corner, double h,
                                                  int count, TexelFilter filter,
                                                  int segments_per_wavelength = 1 << 16) {
    std::vector<glm::dvec3> texels(count, glm::dvec3(0.0));
    const double wavelength = 2.0 * std::numbers::pi / sine.wavenumber;
    const int segments = int(std::ceil((x1 - x0) / wavelength * segments_per_wavelength));
    const double dx = (x1 - x0) / segments;
    // Integral of tent from -infinity to u.
    auto tent_integral = [](double u) {
        if (u <= -1.0) return 0.0;
        if (u <= 0.0) return 0.5 * (u + 1.0) * (u + 1.0);
        if (u <= 1.0) return 1.0 - 0.5 * (1.0 - u) * (1.0 - u);
        return 1.0;
    };
    double left = sine.beam(x0).floor_x;
    for (int s = 0; s < segments; ++s) {
        const double xa = x0 + s * dx, xb = xa + dx;
        const double right = sine.beam(xb).floor_x;
        const SineFloor::Beam mid = sine.beam(0.5 * (xa + xb));
        // Flux per unit length along z, W m^-1.
        const glm::dvec3 flux = sine.sun_irradiance * mid.transmittance * glm::exp(-sine.sigma_t * mid.path) * dx;
        const double lo = std::min(left, right), hi = std::max(left, right), width = hi - lo;
        left = right;
        const int first = int(std::floor((lo - corner) / h)) - 1, last = int(std::floor((hi - corner) / h)) + 1;
        for (int i = std::max(first, 0); i <= std::min(last, count - 1); ++i) {
            const double edge = corner + i * h, centre = edge + 0.5 * h;
            double share = 0.0;  // the fraction of the segment's flux the texel's kernel takes, times h
            if (filter == TexelFilter::Box) {
                share = width > 0.0 ? std::max(0.0, std::min(hi, edge + h) - std::max(lo, edge)) / width
                                    : double(lo >= edge && lo < edge + h);
            } else {
                const double u0 = (lo - centre) / h, u1 = (hi - centre) / h;
                share = width > 1e-12 * h ? (tent_integral(u1) - tent_integral(u0)) / (u1 - u0)
                                          : std::max(0.0, 1.0 - std::abs(u0));
            }
            texels[i] += flux * share / h;
        }
    }
    return texels;
}

}  // namespace vkw::test
