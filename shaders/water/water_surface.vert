#version 450
#extension GL_GOOGLE_include_directive : require
// The water surface drawn from its vertex grid (passes/water/water_surface.hpp), pulled from
// the storage buffer by index: R x R cells, two triangles (six vertices) each.
#include "common/frame_constants.glsl"
#include "water/water_vertex.glsl"

layout(set = 0, binding = 2, std430) readonly buffer Surface { WaterVertex vertices[]; } surface;
layout(push_constant) uniform Params { uint resolution; } params;

layout(location = 0) out vec3 out_position;
layout(location = 1) out vec3 out_normal;

void main() {
    const uvec2 corners[6] = uvec2[](uvec2(0, 0), uvec2(1, 0), uvec2(1, 1), uvec2(0, 0), uvec2(1, 1), uvec2(0, 1));
    uint cell = uint(gl_VertexIndex) / 6u;
    uvec2 ij = uvec2(cell % params.resolution, cell / params.resolution) + corners[uint(gl_VertexIndex) % 6u];
    WaterVertex vertex = surface.vertices[ij.y * (params.resolution + 1u) + ij.x];
    out_position = vertex.position.xyz;
    out_normal = vertex.normal.xyz;
    gl_Position = frame.view_proj * vec4(vertex.position.xyz, 1.0);
}
