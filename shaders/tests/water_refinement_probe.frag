#version 450
#extension GL_GOOGLE_include_directive : require
// The per-pixel refinement's probe (tests/water_gpu/surface_refinement_test.cpp): drawn with
// the water's mesh (water/water_surface.vert), it writes the surface point each pixel shows,
// w = 1 where it refined and 0.5 where it kept the mesh's point.
#include "common/camera_ray.glsl"
#include "water/surface_refinement.glsl"

layout(location = 0) in vec3 in_position;
layout(location = 1) in vec3 in_normal;
layout(location = 2) in vec2 in_parameter;
layout(location = 3) in float in_mesh_sag;  // m: the drawn cell's distance from the surface, at most
layout(location = 0) out vec4 out_point;

void main() {
    vec3 p, normal;
    bool outside;
    const bool refined = water_surface_of_pixel(frame.camera_position.xyz, camera_ray_direction(gl_FragCoord.xy),
                                                in_position, in_normal, in_parameter, in_mesh_sag, p, normal,
                                                outside);
    if (WATER_SCREEN_GRID != 0u && outside) discard;
    out_point = vec4(p, refined ? 1.0 : 0.5);
}
