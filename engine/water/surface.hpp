// The water surface at one fixed time, evaluated on the CPU in double precision. It is the
// ground truth that the GPU surface and the CPU reference renderer are tested against, so
// every model gives exact (analytic) positions, tangents and normals rather than finite
// differences.
//
// A surface is parametric: a grid parameter (x0, z0) maps to
//   P(x0, z0) = (x0 + Dx(x0, z0), level + h(x0, z0), z0 + Dz(x0, z0)),
// where Dx, Dz are the horizontal displacements of Gerstner waves and of a choppy FFT
// ocean (zero for heightfields). World queries ("how high is the water above (x, z)?")
// therefore need the inverse of the horizontal map, which height_at finds by Newton.
#pragma once

#include <memory>

#include <glm/glm.hpp>

#include "engine/water/wave_params.hpp"

namespace vkw {

struct SurfacePoint {
    glm::dvec3 position{0.0};
    glm::dvec3 normal{0.0, 1.0, 0.0};  // unit, oriented so that y > 0 (toward the air)
    glm::dvec3 dP_du{1.0, 0.0, 0.0};   // dP/dx0, tangent along the grid parameter x0
    glm::dvec3 dP_dv{0.0, 0.0, 1.0};   // dP/dz0, tangent along the grid parameter z0
};

// Builds a SurfacePoint from its position and tangents: normal = normalize(cross(dP_dv,
// dP_du)), which is +y for the flat surface, flipped if it points down (only overturned
// parts of a folding surface do). Where the tangents are parallel or zero, |cross| below
// 1e-12 (the cusp of a Gerstner wave at steepness 1), the normal is undefined (the two sides
// of a cusp have opposite horizontal normals); the symmetric choice (0, 1, 0) is returned
// there instead of NaN or rounding noise (docs/model.md section 8).
SurfacePoint make_surface_point(const glm::dvec3& position, const glm::dvec3& dP_du, const glm::dvec3& dP_dv);

class WaterSurface {
public:
    virtual ~WaterSurface();

    // P(x0, z0) = (x0 + Dx, level + h, z0 + Dz) with analytic tangents and normal.
    virtual SurfacePoint at_parameter(double x0, double z0) const = 0;

    // True when there is no horizontal displacement (P.x = x0, P.z = z0 everywhere).
    virtual bool is_heightfield() const = 0;

    // The grid parameter whose displaced point lies above or below the WORLD position
    // (x, z). Heightfields return (x, z). Displaced surfaces solve x0 + Dx(x0, z0) = x,
    // z0 + Dz(x0, z0) = z by Newton's method: start at (x0, z0) = (x, z), Jacobian from the
    // horizontal parts of dP_du and dP_dv, stop when the horizontal miss is <= 1e-12 m or
    // after 50 iterations. A step that does not reduce the miss is halved (up to 40 times),
    // so the iteration cannot diverge; a singular Jacobian (a fold) falls back to the plain
    // fixed-point step. Where the surface folds, several parameters map to (x, z): the one
    // returned is the one Newton reaches from (x, z).
    virtual glm::dvec2 parameter_at(double x, double z) const;

    // Height of the water above y = 0 at the WORLD position (x, z): at_parameter of
    // parameter_at(x, z), its y (this includes the water level).
    virtual double height_at(double x, double z) const;

    // A conservative bound on |h| (the deviation from the mean level), for the frame's
    // needs and the water volume. Each model documents how tight it is.
    virtual double max_amplitude() const = 0;

    // A conservative bound on the slope |grad h| (the tangent of the normal's tilt from +y), for
    // bounding where refracted rays and photons can go; +infinity when the model has none.
    virtual double max_slope() const;

    // A conservative bound on the curvature of the height field, the largest |u^T H u| over unit
    // horizontal u of the Hessian H of h (1/m), for bounding how much the surface focuses the
    // sun's beams; +infinity when the model has none.
    virtual double max_curvature() const;
};

// The surface described by `settings` at `level` (the mean water level, m) and `time` (s).
// Throws vkw::UserError (validate_waves) for settings a scene must not contain.
std::unique_ptr<WaterSurface> make_surface(const WaveSettings& settings, double level, double time);

// A bound on |h| for the frame's needs and culling margins, at a cost a frame can pay every
// time: the sums of sines and Gerstner waves give their surface's own max_amplitude(); the FFT
// ocean gives its spectrum's all-time bound 2 sum |h0| (FftOceanSpectrum::amplitude_bound, kept
// while the spectrum stays), not the tighter sum |h~(k, t)| of its surface at `time`, which
// costs a complex exponential per mode (65,536 of them at 256^2: milliseconds of CPU a frame).
double frame_amplitude_bound(const WaveSettings& settings, double level, double time);

// max_slope() and max_curvature() of the surface, at a cost a frame can pay every time: the sums of
// sines and Gerstner waves give their surface's own bounds, which read only the waves' amplitudes,
// wave vectors and steepness (the clock does not move them), kept per thread while the waves stay,
// so that a running clock builds no surface for them; flat water 0; the FFT ocean, which has
// neither bound, +infinity.
struct ShapeBounds {
    double slope = 0.0;
    double curvature = 0.0;
};
ShapeBounds frame_shape_bounds(const WaveSettings& settings, double level, double time);

}  // namespace vkw
