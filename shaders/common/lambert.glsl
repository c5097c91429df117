// Lambertian receivers above the water (docs/model.md section 1): L = rho E / pi with
// E = E_s max(0, -s.N) V (direct sun, V the visibility of the sun) + pi L_sky_avg (skylight,
// no occlusion). V is the sun shadow map's compare with VKWATER_SUN_SHADOW (the scene has
// objects) and 1 without.
#ifndef VKWATER_LAMBERT_GLSL
#define VKWATER_LAMBERT_GLSL

#include "common/frame_constants.glsl"
#ifdef VKWATER_SUN_SHADOW
#include "receivers/sun_shadow.glsl"
#endif

const float PI = 3.14159265358979323846;

vec3 receiver_irradiance_above_water(vec3 p, vec3 normal) {
    bool sun_up = frame.sun_direction.w > 0.5;
    float cos_sun = sun_up ? max(0.0, dot(normal, -frame.sun_direction.xyz)) : 0.0;
#ifdef VKWATER_SUN_SHADOW
    if (cos_sun > 0.0) cos_sun *= sun_visibility(p, cos_sun);
#endif
    return frame.sun_irradiance.rgb * cos_sun + PI * frame.sky_average.rgb;
}

vec3 lambert_radiance(vec3 albedo, vec3 irradiance) {
    return albedo * irradiance / PI;
}

#endif
