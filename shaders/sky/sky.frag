#version 450
#extension GL_GOOGLE_include_directive : require
// The sky seen directly: constant radiance plus the sun's disk.
#include "common/camera_ray.glsl"
#include "common/sky.glsl"

layout(location = 0) out vec4 out_radiance;

void main() {
    out_radiance = vec4(sky_radiance(camera_ray_direction(gl_FragCoord.xy)), 1.0);
}
