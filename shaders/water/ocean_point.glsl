// The FFT ocean's surface at one grid parameter, from its eight fields on the periodic n x n
// grid (after ocean_spectra.comp and ocean_fft.comp): the parameter (x0, z0) samples the fields
// bilinearly between the four surrounding grid nodes (wrapping around the patch), then builds
// the point as engine/water/fft_ocean.cpp ocean_surface_point does:
//   P = (x0 + Dx, level + h, z0 + Dz),  dP/du = (1 + dDx/dx0, dh/dx0, dDx/dz0),
//   dP/dv = (dDx/dz0, dh/dz0, 1 + dDz/dz0).
// Shared by the grid kernel (ocean_grid.comp) and the water's per-pixel refinement
// (water/surface_refinement.glsl). The includer defines OCEAN_FIELDS_BINDING, the binding of
// the fields in set 0.
#ifndef VKWATER_OCEAN_POINT_GLSL
#define VKWATER_OCEAN_POINT_GLSL

layout(set = 0, binding = OCEAN_FIELDS_BINDING, std430) readonly buffer Grids { vec4 grids[]; };

// Grid q of the FFT's output, bilinearly between the four nodes around: fields 4q .. 4q + 3
// in x, y, z, w (plane p holds fields 2p and 2p + 1; grid q planes 2q and 2q + 1).
vec4 sample_ocean_grid(uint q, uint n, uvec2 lo, uvec2 hi, vec2 w) {
    const uint base = q * n * n;
    const vec4 f00 = grids[base + lo.y * n + lo.x], f10 = grids[base + lo.y * n + hi.x];
    const vec4 f01 = grids[base + hi.y * n + lo.x], f11 = grids[base + hi.y * n + hi.x];
    return mix(mix(f00, f10, w.x), mix(f01, f11, w.x), w.y);
}

// n: nodes per side (a power of two); nodes_per_metre: n / patch_size.
void ocean_point(vec2 x, float level, uint n, float nodes_per_metre, out vec3 position, out vec3 dP_du,
                 out vec3 dP_dv) {
    const vec2 u = x * nodes_per_metre;
    const vec2 cell = floor(u);
    const vec2 w = u - cell;
    // Node indices modulo n (a power of two; & of the two's complement wraps negatives).
    const int mask = int(n) - 1;
    const ivec2 c = ivec2(cell);
    const uvec2 lo = uvec2(c & mask), hi = uvec2((c + 1) & mask);
    // h, Dx, Dz, dh/dx0 and dh/dz0, dDx/dx0, dDx/dz0, dDz/dz0 (the OceanField order).
    const vec4 a = sample_ocean_grid(0, n, lo, hi, w), b = sample_ocean_grid(1, n, lo, hi, w);
    position = vec3(x.x + a.y, level + a.x, x.y + a.z);
    dP_du = vec3(1.0 + b.y, a.w, b.z);
    dP_dv = vec3(b.z, b.x, 1.0 + b.w);
}

#endif
