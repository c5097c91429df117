// The water surface's vertex grid, shared by every wave model's kernel: the parameter of
// each vertex, the normal from the tangents (engine/water/surface.cpp make_surface_point,
// in fp32), and the vertex layout that passes/water/water_surface.hpp documents.
#ifndef VKWATER_WATER_VERTEX_GLSL
#define VKWATER_WATER_VERTEX_GLSL

// std430: 32 bytes per vertex, (R + 1)^2 of them, row j (z0) after row j - 1, i along x0.
struct WaterVertex {
    vec4 position;  // xyz world position, w = 1
    vec4 normal;    // xyz unit normal toward the air (y > 0), w = 0
};

// The head of every grid kernel's push constants; its C++ type, WaterGridPush in
// passes/water/water_surface_grid.hpp, is generated once from common/shared_blocks.comp.
// One dispatch writes a band of rows, first_row .. first_row + band_rows - 1, into a vertex
// buffer binding that starts at row first_row: a storage-buffer binding is limited to
// maxStorageBufferRange (128 MiB on lavapipe, R = 2047), and large grids take several bands.
struct WaterGrid {
    float level;        // mean water level y, m
    float half_extent;  // E: the grid spans [-E, E]^2
    uint resolution;    // R cells per side
    uint first_row;
    uint band_rows;
};

// The grid parameter of vertex (i, j): -E + 2 E i / R, written as the CPU writes it
// (engine/water/water_volume.cpp), E (2 i - R) / R, so that both ends are exactly -E and E.
vec2 water_grid_parameter(uvec2 ij, WaterGrid grid) {
    const float r = float(grid.resolution);
    return grid.half_extent * (2.0 * vec2(ij) - r) / r;
}

// normalize(cross(dP/dv, dP/du)) turned toward +y. Where |cross| is at most this the tangents
// are parallel to fp32 rounding (a Gerstner cusp) and the direction would be noise: (0, 1, 0)
// instead, as the CPU does below its double-precision threshold of 1e-12.
const float kDegenerateAreaRatio = 1e-6;

vec3 water_normal(vec3 dP_du, vec3 dP_dv) {
    const vec3 n = cross(dP_dv, dP_du);
    const float len = length(n);
    if (!(len > kDegenerateAreaRatio) || isinf(len)) {
        return vec3(0.0, 1.0, 0.0);
    }
    return n.y < 0.0 ? -n / len : n / len;
}

WaterVertex make_water_vertex(vec3 position, vec3 dP_du, vec3 dP_dv) {
    return WaterVertex(vec4(position, 1.0), vec4(water_normal(dP_du, dP_dv), 0.0));
}

#endif
