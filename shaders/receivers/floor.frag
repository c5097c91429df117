#version 450
#extension GL_GOOGLE_include_directive : require
// The floor as a Lambertian receiver lit by the sun and the sky.
#include "common/lambert.glsl"

layout(location = 0) in vec3 in_world_position;
layout(location = 0) out vec4 out_radiance;

void main() {
    vec3 irradiance = receiver_irradiance_above_water(vec3(0.0, 1.0, 0.0));
    out_radiance = vec4(lambert_radiance(frame.floor_albedo.rgb, irradiance), 1.0);
}
