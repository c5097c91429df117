#version 450
#extension GL_GOOGLE_include_directive : require
// The water surface with the simplest correct lookups (PHYSICS.md sections 1-3, 6, 7):
// exact Fresnel and total internal reflection, the sky and the sun's disk in reflection,
// refraction down to the floor plane, radiance scaled by n^2 across the surface, sigma_t
// attenuation and single scattering along every path in the water. From above and, for
// a camera in the water, from below (Snell's window). Variants (shaders/CMakeLists.txt):
// VKWATER_PER_PIXEL_MEDIUM (the stencil split's mask) and VKWATER_CAUSTICS (the floor seen
// through the water reads the caustic map).
#include "common/camera_ray.glsl"
#include "common/fresnel.glsl"
#include "common/medium.glsl"
#include "common/sky.glsl"
#include "water_shading/camera_medium.glsl"
#include "water_shading/underwater_light.glsl"

layout(set = 0, binding = 1, std430) readonly buffer Optics { SceneOptics optics; };

layout(location = 0) in vec3 in_position;
layout(location = 1) in vec3 in_normal;
layout(location = 0) out vec4 out_radiance;

// Radiance arriving at p along d inside the water: the floor it meets, attenuated, plus
// the sun's beam scattered along the way.
vec3 radiance_in_water(vec3 p, vec3 d) {
    float length_in_water;
    vec3 behind;
    if (!floor_along(p, d, optics, length_in_water, behind)) length_in_water = 0.0;
    return water_path_radiance(analytic_inscatter_sigma_s(), frame.medium_sigma_t.rgb, frame.medium_sigma_s.w,
                               max(0.0, frame.water.x - p.y), length_in_water, d, optics.refracted_sun.xyz,
                               optics.e_perp0.rgb, behind);
}

void main() {
    vec3 p = in_position;
    vec3 normal = normalize(in_normal);  // toward the air
    vec3 eye = frame.camera_position.xyz;
    vec3 v = normalize(p - eye);
    float n = frame.water.y;

    if (!camera_in_water()) {
        // From the air. A wave's back face seen from above keeps a grazing cosine of 0.
        Fresnel f = fresnel_exact(max(0.0, -dot(v, normal)), 1.0, n);
        vec3 reflected = sky_radiance(reflect(v, normal));
        vec3 refracted_direction;
        vec3 transmitted = vec3(0.0);
        if (refract_direction(v, normal, 1.0 / n, refracted_direction)) {
            transmitted = radiance_in_water(p, refracted_direction) / (n * n);
        }
        out_radiance = vec4(f.R * reflected + f.T * transmitted, 1.0);
        return;
    }
    // From the water: total internal reflection outside Snell's window.
    vec3 water_side = -normal;
    Fresnel f = fresnel_exact(max(0.0, dot(v, normal)), n, 1.0);
    vec3 at_surface = f.R * radiance_in_water(p, reflect(v, water_side));
    vec3 to_air;
    if (!f.total_internal_reflection && refract_direction(v, water_side, n, to_air)) {
        at_surface += f.T * n * n * sky_radiance(to_air);
    }
    float camera_depth = max(0.0, frame.water.x - eye.y);
    out_radiance = vec4(water_path_radiance(analytic_inscatter_sigma_s(), frame.medium_sigma_t.rgb,
                                            frame.medium_sigma_s.w, camera_depth, distance(eye, p), v,
                                            optics.refracted_sun.xyz, optics.e_perp0.rgb, at_surface),
                        1.0);
}
