#version 450
#extension GL_GOOGLE_include_directive : require
// The water surface drawn from its mesh's vertices (passes/water/water_surface.hpp), pulled from
// the storage buffer by index: M x M cells, one triangle strip of 2 (M + 1) vertices per row
// (a third of the vertices a list of two triangles per cell takes). The grid
// parameter goes along for the fragment shader's per-pixel refinement to start from.
#include "common/frame_constants.glsl"
#include "water/water_surface_params.glsl"
#include "water/water_vertex.glsl"

layout(set = 0, binding = 2, std430) readonly buffer Surface { WaterVertex vertices[]; } surface;

layout(location = 0) out vec3 out_position;
layout(location = 1) out vec3 out_normal;
layout(location = 2) out vec2 out_parameter;
layout(location = 3) out float out_mesh_sag;

void main() {
    // Row j of cells is instance j, one triangle strip zig-zagging between vertex rows j and j + 1.
    const uint m = params.mesh_resolution;
    uvec2 ij = uvec2(uint(gl_VertexIndex) / 2u, uint(gl_InstanceIndex) + (uint(gl_VertexIndex) & 1u));
    WaterVertex vertex = surface.vertices[ij.y * (m + 1u) + ij.x];
    out_position = vertex.position.xyz;
    out_normal = vertex.normal.xyz;
    // As water_grid_parameter (water/water_vertex.glsl) computes it for the mesh's kernel.
    out_parameter = params.half_extent * (2.0 * vec2(ij) - float(m)) / float(m);
    out_mesh_sag = params.mesh_sag;
    gl_Position = frame.view_proj * vec4(vertex.position.xyz, 1.0);
}
