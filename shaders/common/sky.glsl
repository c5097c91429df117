// Sky radiance of the model (PHYSICS.md section 1): a constant per channel, plus the
// sun's disk (angular radius 0.2666 degrees, solid angle 6.80e-5 sr) with radiance
// E_s / 6.80e-5, which only shows (in view and in reflections) and lights nothing.
#ifndef VKWATER_SKY_GLSL
#define VKWATER_SKY_GLSL

#include "common/frame_constants.glsl"

vec3 sky_radiance(vec3 direction) {
    vec3 radiance = frame.sky_radiance.rgb;
    bool sun_up = frame.sun_direction.w > 0.5;
    if (sun_up && dot(direction, -frame.sun_direction.xyz) >= frame.sun_disk.x) {
        radiance += frame.sun_irradiance.rgb / frame.sun_disk.y;
    }
    return radiance;
}

#endif
