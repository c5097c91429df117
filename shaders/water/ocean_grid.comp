#version 450
#extension GL_GOOGLE_include_directive : require
// The FFT ocean's vertices (water/ocean_point.glsl at every vertex parameter of the grid).
// Where a vertex falls on a node (2E/R a multiple of patch_size / n, -E on a node, and the
// fp32 parameter and x0 n / patch_size exact, as with powers of two) the weights are exactly
// 0 and 1 and the vertex is the FFT grid's value there: tests/water_gpu compares those with
// engine/water's evaluate_ocean_grid, and other vertices with its grid interpolated alike.
#define OCEAN_FIELDS_BINDING 0
#include "water/ocean_point.glsl"
#include "water/water_grid_invocation.glsl"

layout(local_size_x = 8, local_size_y = 8) in;

layout(set = 0, binding = 1, std430) writeonly buffer Vertices { WaterVertex vertices[]; };
layout(push_constant) uniform Params {
    WaterGrid grid;
    uint n;
    float nodes_per_metre;  // n / patch_size
} params;

void main() {
    uvec2 ij;
    uint slot;
    if (!water_vertex_of_invocation(params.grid, ij, slot)) return;
    vec3 position, dP_du, dP_dv;
    ocean_point(water_grid_parameter(ij, params.grid), params.grid.level, params.n, params.nodes_per_metre, position,
                dP_du, dP_dv);
    vertices[slot] = make_water_vertex(position, dP_du, dP_dv);
}
