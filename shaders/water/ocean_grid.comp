#version 450
#extension GL_GOOGLE_include_directive : require
// The FFT ocean's vertices from its eight fields on the periodic n x n grid (after
// ocean_spectra.comp and ocean_fft.comp): each vertex parameter (x0, z0) samples the fields
// bilinearly between the four surrounding grid nodes (wrapping around the patch), then
// builds the point as engine/water/fft_ocean.cpp ocean_surface_point does:
//   P = (x0 + Dx, level + h, z0 + Dz),  dP/du = (1 + dDx/dx0, dh/dx0, dDx/dz0),
//   dP/dv = (dDx/dz0, dh/dz0, 1 + dDz/dz0),  normal = normalize(cross(dP/dv, dP/du)).
// Where a vertex falls on a node (2E/R a multiple of patch_size / n, -E on a node, and the
// fp32 parameter and x0 n / patch_size exact, as with powers of two) the weights are exactly
// 0 and 1 and the vertex is the FFT grid's value there: tests/water_gpu compares those with
// engine/water's evaluate_ocean_grid, and other vertices with its grid interpolated alike.
#include "water/water_grid_invocation.glsl"

layout(local_size_x = 8, local_size_y = 8) in;

layout(set = 0, binding = 0, std430) readonly buffer Grids { vec4 grids[]; };
layout(set = 0, binding = 1, std430) writeonly buffer Vertices { WaterVertex vertices[]; };
layout(push_constant) uniform Params {
    WaterGrid grid;
    uint n;
    float nodes_per_metre;  // n / patch_size
} params;

// Grid q of the FFT's output, bilinearly between the four nodes around: fields 4q .. 4q + 3
// in x, y, z, w (plane p holds fields 2p and 2p + 1; grid q planes 2q and 2q + 1).
vec4 sample_grid(uint q, uvec2 lo, uvec2 hi, vec2 w) {
    const uint base = q * params.n * params.n;
    const vec4 f00 = grids[base + lo.y * params.n + lo.x], f10 = grids[base + lo.y * params.n + hi.x];
    const vec4 f01 = grids[base + hi.y * params.n + lo.x], f11 = grids[base + hi.y * params.n + hi.x];
    return mix(mix(f00, f10, w.x), mix(f01, f11, w.x), w.y);
}

void main() {
    uvec2 ij;
    uint slot;
    if (!water_vertex_of_invocation(params.grid, ij, slot)) return;
    const vec2 x = water_grid_parameter(ij, params.grid);
    const vec2 u = x * params.nodes_per_metre;
    const vec2 cell = floor(u);
    const vec2 w = u - cell;
    // Node indices modulo n (a power of two; & of the two's complement wraps negatives).
    const int mask = int(params.n) - 1;
    const ivec2 c = ivec2(cell);
    const uvec2 lo = uvec2(c & mask), hi = uvec2((c + 1) & mask);
    // h, Dx, Dz, dh/dx0 and dh/dz0, dDx/dx0, dDx/dz0, dDz/dz0 (the OceanField order).
    const vec4 a = sample_grid(0, lo, hi, w), b = sample_grid(1, lo, hi, w);
    const vec3 position = vec3(x.x + a.y, params.grid.level + a.x, x.y + a.z);
    const vec3 dP_du = vec3(1.0 + b.y, a.w, b.z);
    const vec3 dP_dv = vec3(b.z, b.x, 1.0 + b.w);
    vertices[slot] = make_water_vertex(position, dP_du, dP_dv);
}
