// Sky radiance of the model (docs/model.md section 1): a constant per channel or the
// gradient of scenes/README.md, plus the sun's disk (angular radius 0.2666 degrees,
// solid angle 6.80e-5 sr) with radiance E_s / 6.80e-5, which only shows (in view and
// in reflections) and lights nothing.
#ifndef VKWATER_SKY_GLSL
#define VKWATER_SKY_GLSL

#include "common/frame_constants.glsl"

// Without the sun's disk: L = mix(horizon, zenith, dir.y^exponent) above the horizon,
// the ground radiance below (the same formula as vkw::sky_radiance on the CPU).
vec3 sky_base_radiance(vec3 direction) {
    if (frame.sky_params.x < 0.5) return frame.sky_radiance.rgb;
    if (direction.y < 0.0) return frame.sky_ground.rgb;
    return mix(frame.sky_horizon.rgb, frame.sky_zenith.rgb, pow(direction.y, frame.sky_params.y));
}

vec3 sky_radiance(vec3 direction) {
    vec3 radiance = sky_base_radiance(direction);
    bool sun_up = frame.sun_direction.w > 0.5;
    if (sun_up && dot(direction, -frame.sun_direction.xyz) >= frame.sun_disk.x) {
        radiance += frame.sun_irradiance.rgb / frame.sun_disk.y;
    }
    return radiance;
}

#endif
