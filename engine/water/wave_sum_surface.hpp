// A sum of directional sine and Gerstner waves with analytic first derivatives (Guardado & Sánchez-Crespo 2004's
// "derivatives, not finite differences"; the Gerstner form of GPU Gems 1 ch. 1, y up).
//
// For wave i with amplitude A, wave number k = 2 pi / wavelength, unit direction of travel
// d = (cos a, sin a) in the xz-plane, angular frequency w (= k speed, or sqrt(g k) for the
// deep-water default), phase offset p and steepness s:
//   theta = k (d . (x0, z0)) - w t + p
//   h     = sum A sin(theta)
//   D     = sum (s / k) d cos(theta)        (Q A = s / k: zero for a sine, s = 0)
// so dP/du = (1 - sum s d_x d_x sin, sum A k d_x cos, -sum s d_x d_z sin) and dP/dv
// likewise with d_z. h is measured from `level`.
#pragma once

#include <vector>

#include "engine/water/surface.hpp"
#include "engine/water/wave_terms.hpp"

namespace vkw {

class WaveSumSurface final : public WaterSurface {
public:
    // Throws vkw::UserError (validate_waves) for bad components or a steepness sum above 1
    // without allow_folding. settings.model is not consulted: the components are used.
    WaveSumSurface(const WaveSettings& settings, double level, double time);

    SurfacePoint at_parameter(double x0, double z0) const override;
    bool is_heightfield() const override { return heightfield_; }
    // sum of A_i: a true bound (reached where all crests coincide).
    double max_amplitude() const override { return amplitude_sum_; }
    // G / (1 - sum s_i): the height's gradient in the parameters, sum A k d cos(theta), is at most
    // G = max over unit u of sum A k |d . u| (the largest point of the zonotope the terms span;
    // for perpendicular equal waves sqrt(2) A k, not 2 A k), and the horizontal map (x0, z0) ->
    // (x, z) shrinks no length by more than 1 - sum s (each Gerstner term subtracts
    // s sin(theta) d d^T); +infinity when sum s >= 1 (folding allowed).
    double max_slope() const override { return slope_bound_; }
    // Sines alone: sum of A_i k_i^2, since H = -sum A k^2 sin(theta) d d^T and |u^T d d^T u| <= 1
    // (reached where every term's sine is 1 and the directions agree). With a Gerstner term the
    // surface is no height field of (x0, z0) and no bound is computed: +infinity.
    double max_curvature() const override { return curvature_bound_; }

private:
    std::vector<WaveTerms> waves_;
    double level_;
    double amplitude_sum_ = 0.0;
    double slope_bound_ = 0.0;
    double curvature_bound_ = 0.0;
    bool heightfield_ = true;
};

}  // namespace vkw
