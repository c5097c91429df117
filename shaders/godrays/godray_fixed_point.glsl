// The fixed-point unit of the godray radiance accumulation (passes/godrays/godrays_lines.hpp), from the
// frame constants alone, so that the line walk and the resolve agree without a buffer between them:
//   LSB = L_ref 2^-28,  L_ref = max_c E_s,c * max_c sigma_s,c min(1 / sigma_t,c, D) / (4 pi),
// D the water's depth (mean level to floor, at least 1 mm): the in-scatter of an isotropic medium
// along a horizontal ray of length min(1 / sigma_t, D), the size of what a pixel collects. A
// deposit rounds by at most LSB / 2 = 1.9e-9 L_ref, and one is clamped to 2^50 LSB = 4.2e6 L_ref,
// so a pixel's uint64 overflows only after 2^14 clamped deposits.
#ifndef VKWATER_GODRAY_FIXED_POINT_GLSL
#define VKWATER_GODRAY_FIXED_POINT_GLSL

#include "common/frame_constants.glsl"

const float kGodrayMaxDeposit = 1125899906842624.0;  // 2^50 LSB

float godray_lsb() {
    const vec3 sigma_t = max(frame.medium_sigma_t.rgb, vec3(1e-30));
    const float depth = max(frame.water.x - frame.floor_plane.x, 1e-3);
    const vec3 reach = frame.medium_sigma_s.rgb * min(1.0 / sigma_t, vec3(depth));
    const float e_s = max(frame.sun_irradiance.r, max(frame.sun_irradiance.g, frame.sun_irradiance.b));
    const float reference = e_s * max(reach.r, max(reach.g, reach.b)) / (4.0 * 3.14159265358979323846);
    // No sun or no scattering: nothing deposits; any positive unit will do.
    return reference > 0.0 ? reference * 3.7252902984619140625e-9 : 1.0;  // 2^-28
}

#endif
