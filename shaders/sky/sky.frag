#version 450
#extension GL_GOOGLE_include_directive : require
// The sky seen directly: constant radiance plus the sun's disk, behind everything the
// later passes draw. A camera ray that starts in the water and meets nothing (neither the
// surface nor a receiver: it leaves the water body through its side) sees nothing (docs/model.md
// section 1; the scenes close their water with a floor or walls). Variants: per_pixel
// (VKWATER_PER_PIXEL_MEDIUM, the stencil split's mask) and frame (the per-frame medium).
#include "common/camera_ray.glsl"
#include "common/sky.glsl"
#include "water/camera_medium.glsl"

layout(location = 0) out vec4 out_radiance;

void main() {
    vec3 sky = camera_in_water() ? vec3(0.0) : sky_radiance(camera_ray_direction(gl_FragCoord.xy));
    out_radiance = vec4(sky, 1.0);
}
