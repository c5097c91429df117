#version 450
#extension GL_GOOGLE_include_directive : require
// The sky seen directly: constant radiance plus the sun's disk, behind everything the
// later passes draw. A camera ray that starts in the water and meets nothing (neither the
// surface nor a receiver) leaves the water body through its side and sees nothing (docs/model.md
// section 1; the scenes close their water with a floor or walls), except under infinite water
// (VKWATER_INFINITE_WATER), where it runs to the water's bottom and brings the sun's light
// scattered along the way. Variants: per_pixel (VKWATER_PER_PIXEL_MEDIUM, the stencil split's
// mask) and frame (the per-frame medium), each also with VKWATER_INFINITE_WATER.
#include "common/camera_ray.glsl"
#include "common/sky.glsl"
#include "water/camera_medium.glsl"

#ifdef VKWATER_INFINITE_WATER
#include "common/medium.glsl"
#include "water/scene_optics.glsl"
#include "water/water_bottom.glsl"

layout(set = 0, binding = 1, std430) readonly buffer Optics { SceneOptics optics; };

// What a camera ray in infinite water that meets nothing brings: the in-scatter of its run to
// the bottom (frame.camera_medium.y; no farther than the far field, camera_medium.z), as a
// refracted ray that meets nothing brings in the water's shading.
vec3 radiance_of_ray_meeting_nothing(vec3 d) {
    const vec3 eye = frame.camera_position.xyz;
    const float run = run_to_water_bottom(eye, d, frame.camera_medium.y, frame.camera_medium.z);
    return water_path_radiance(analytic_inscatter_sigma_s(), frame.medium_sigma_t.rgb, frame.medium_sigma_s.w,
                               max(0.0, frame.water.x - eye.y), run, d, optics.refracted_sun.xyz, optics.e_perp0.rgb,
                               vec3(0.0));
}
#else
vec3 radiance_of_ray_meeting_nothing(vec3 d) { return vec3(0.0); }
#endif

layout(location = 0) out vec4 out_radiance;

void main() {
    const vec3 d = camera_ray_direction(gl_FragCoord.xy);
    const vec3 radiance = camera_in_water() ? radiance_of_ray_meeting_nothing(d) : sky_radiance(d);
    out_radiance = vec4(radiance, 1.0);
}
