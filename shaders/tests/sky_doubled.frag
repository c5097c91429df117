#version 450
#extension GL_GOOGLE_include_directive : require
// Viewer test (tests/view/view_window_test.cpp): sky/sky.frag with twice its radiance, copied
// over sky/sky.frag.frame.spv (the variant for a camera above the water) while the viewer runs, to see that a shader reload re-reads the file.
#include "common/camera_ray.glsl"
#include "common/sky.glsl"

layout(location = 0) out vec4 out_radiance;

void main() {
    out_radiance = vec4(2.0 * sky_radiance(camera_ray_direction(gl_FragCoord.xy)), 1.0);
}
