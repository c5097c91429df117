#version 450
#extension GL_GOOGLE_include_directive : require
// The water surface drawn from its mesh's vertices (passes/water/water_surface.hpp), pulled from
// the storage buffer by index: M x M cells, two triangles (six vertices) each. The grid
// parameter goes along for the fragment shader's per-pixel refinement to start from.
#include "common/frame_constants.glsl"
#include "water/water_surface_params.glsl"
#include "water/water_vertex.glsl"

layout(set = 0, binding = 2, std430) readonly buffer Surface { WaterVertex vertices[]; } surface;

layout(location = 0) out vec3 out_position;
layout(location = 1) out vec3 out_normal;
layout(location = 2) out vec2 out_parameter;

void main() {
    const uvec2 corners[6] = uvec2[](uvec2(0, 0), uvec2(1, 0), uvec2(1, 1), uvec2(0, 0), uvec2(1, 1), uvec2(0, 1));
    const uint m = params.mesh_resolution;
    uint cell = uint(gl_VertexIndex) / 6u;
    uvec2 ij = uvec2(cell % m, cell / m) + corners[uint(gl_VertexIndex) % 6u];
    WaterVertex vertex = surface.vertices[ij.y * (m + 1u) + ij.x];
    out_position = vertex.position.xyz;
    out_normal = vertex.normal.xyz;
    // As water_grid_parameter (water/water_vertex.glsl) computes it for the mesh's kernel.
    out_parameter = params.half_extent * (2.0 * vec2(ij) - float(m)) / float(m);
    gl_Position = frame.view_proj * vec4(vertex.position.xyz, 1.0);
}
