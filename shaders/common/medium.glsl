// The water as a participating medium (docs/model.md sections 1 and 6): per-channel
// extinction of every unscattered path, the Henyey-Greenstein phase function, and the
// analytic single scattering of the sun's refracted beam along a view ray in water
// under a flat surface. Optical depth is carried and exponentiated once; no division
// by a transmittance.
#ifndef VKWATER_MEDIUM_GLSL
#define VKWATER_MEDIUM_GLSL

const float MEDIUM_PI = 3.14159265358979323846;

vec3 transmittance(vec3 optical_depth) { return exp(-optical_depth); }

// Henyey-Greenstein, per steradian; g in (-1, 1).
float henyey_greenstein(float cos_angle, float g) {
    float denominator = max(1.0 + g * g - 2.0 * g * cos_angle, 1e-12);
    return (1.0 - g * g) / (4.0 * MEDIUM_PI * denominator * sqrt(denominator));
}

// (1 - exp(-x)) / x for x >= 0. GLSL has no expm1: below 0.1 a Taylor series (the
// first omitted term is x^5/720 < 1.4e-8 relative); above, the cancellation in
// 1 - exp(-x) costs at most 2^-24 / 0.1 < 6e-7 relative.
float one_minus_exp_over_x(float x) {
    if (x < 0.1) return 1.0 - x * (0.5 - x * (1.0 / 6.0 - x * (1.0 / 24.0 - x * (1.0 / 120.0))));
    return (1.0 - exp(-x)) / x;
}
vec3 one_minus_exp_over_x(vec3 x) {
    return vec3(one_minus_exp_over_x(x.r), one_minus_exp_over_x(x.g), one_minus_exp_over_x(x.b));
}

// Radiance in the water along a view segment (docs/model.md section 6): it starts at
// depth z0 >= 0, runs a length s in unit direction v and ends at radiance l_behind;
// the sun's refracted beam t (unit, t.y < 0) has irradiance e_perp0 on a plane normal
// to it just below the surface. Per channel.
vec3 water_path_radiance(vec3 sigma_s, vec3 sigma_t, float g, float z0, float s, vec3 v, vec3 t, vec3 e_perp0,
                         vec3 l_behind) {
    float cos_t = -t.y;
    float c = -v.y / cos_t;
    float phase = henyey_greenstein(dot(t, -v), g);
    // exp(-tau0) (1 - exp(-x)) / x, rewritten for x < 0 (a ray rising faster than the
    // beam sinks) as exp(-(tau0 + x)) (1 - exp(x)) / (-x), where tau0 + x >= 0 is the
    // optical depth at the shallow end: no exponential can overflow.
    vec3 tau0 = sigma_t * (z0 / cos_t);
    vec3 x = sigma_t * (s * (1.0 + c));
    vec3 beam = (1.0 + c) >= 0.0 ? exp(-tau0) * one_minus_exp_over_x(x)
                                 : exp(-(tau0 + x)) * one_minus_exp_over_x(-x);
    return l_behind * exp(-sigma_t * s) + sigma_s * phase * e_perp0 * s * beam;
}

#endif
