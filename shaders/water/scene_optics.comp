#version 450
#extension GL_GOOGLE_include_directive : require
// One invocation: the water's optical constants for this frame, from the shared
// Fresnel include (no C++ copy of it exists in the real-time renderer).
// T_hemi(n) = 2 * integral_0^{pi/2} T cos sin d(theta) = 2 * integral_0^1 T(mu) mu d(mu): the
// integrand is analytic on [0, 1] for n > 1 (cos_t never reaches 0 from the air side),
// so 16-point Gauss-Legendre is exact to fp32 precision.
#include "common/fresnel.glsl"
#include "common/frame_constants.glsl"
#include "water/scene_optics.glsl"

layout(local_size_x = 1) in;
layout(set = 0, binding = 1, std430) writeonly buffer Optics { SceneOptics optics; };

const float GL_NODES[8] = float[](0.0950125098, 0.2816035508, 0.4580167777, 0.6178762444,
                                  0.7554044084, 0.8656312024, 0.9445750231, 0.9894009350);
const float GL_WEIGHTS[8] = float[](0.1894506105, 0.1826034150, 0.1691565194, 0.1495959888,
                                    0.1246289713, 0.0951585117, 0.0622535239, 0.0271524594);

void main() {
    float n = frame.water.w > 0.5 ? frame.water.y : 1.0;
    float t_hemi = 0.0;
    for (int k = 0; k < 8; ++k) {
        // Nodes +-x_k on [-1, 1] mapped to mu = (1 +- x_k) / 2 on [0, 1].
        for (int sign = -1; sign <= 1; sign += 2) {
            float mu = 0.5 * (1.0 + float(sign) * GL_NODES[k]);
            t_hemi += GL_WEIGHTS[k] * fresnel_exact(mu, 1.0, n).T * mu;
        }
    }


    vec3 s = frame.sun_direction.xyz;
    bool sun_up = frame.sun_direction.w > 0.5;
    float cos_s = max(0.0, -s.y);
    Fresnel at_surface = fresnel_exact(cos_s, 1.0, n);
    vec3 t = vec3(0.0, -1.0, 0.0);
    if (!refract_direction(s, vec3(0.0, 1.0, 0.0), 1.0 / n, t)) t = vec3(0.0, -1.0, 0.0);  // never from the air side
    float cos_t = max(-t.y, 1e-6);
    vec3 e_perp0 = sun_up ? frame.sun_irradiance.rgb * (cos_s * at_surface.T / cos_t) : vec3(0.0);
    optics = SceneOptics(vec4(t, cos_t), vec4(e_perp0, 0.0), vec4(t_hemi, at_surface.T, 0.0, 0.0));
}
