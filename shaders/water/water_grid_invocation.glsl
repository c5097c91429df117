// Which grid vertex a compute invocation writes (the kernels of shaders/water/), kept
// apart from water_vertex.glsl so that graphics stages can include the vertex layout.
#ifndef VKWATER_WATER_GRID_INVOCATION_GLSL
#define VKWATER_WATER_GRID_INVOCATION_GLSL

#include "water/water_vertex.glsl"

// This invocation's vertex (i, j) and its slot in the band's binding; false for the
// invocations past the grid's or the band's end.
bool water_vertex_of_invocation(WaterGrid grid, out uvec2 ij, out uint slot) {
    ij = uvec2(gl_GlobalInvocationID.x, gl_GlobalInvocationID.y + grid.first_row);
    slot = gl_GlobalInvocationID.y * (grid.resolution + 1) + gl_GlobalInvocationID.x;
    return gl_GlobalInvocationID.x <= grid.resolution && gl_GlobalInvocationID.y < grid.band_rows;
}

#endif
