#version 450
// The FFT ocean's largest |height| this frame: the largest |h| over the grid's nodes, written into
// the vec4 after the fields (grids[2 n^2].x; passes/water/water_surface_ocean.hpp). Between the
// nodes the GPU's surface is the fields' bilinear patch (water/ocean_point.glsl), which never
// leaves the range of its four corners, so this bounds the whole surface's height exactly, where
// the CPU's bound (2 sum |h0|, good for every time) is several times larger. The per-pixel march
// and the camera medium's undecided band read it (water/surface_refinement.glsl). One work group.
layout(local_size_x = 256) in;

layout(set = 0, binding = 0, std430) buffer Grids { vec4 grids[]; };
layout(push_constant) uniform Params {
    uint n;  // nodes per side
} params;

shared float largest[256];

void main() {
    const uint nodes = params.n * params.n;
    const uint lane = gl_LocalInvocationIndex;
    float m = 0.0;
    for (uint i = lane; i < nodes; i += 256u) m = max(m, abs(grids[i].x));  // grid 0's x: h
    largest[lane] = m;
    barrier();
    for (uint half_width = 128u; half_width > 0u; half_width >>= 1) {
        if (lane < half_width) largest[lane] = max(largest[lane], largest[lane + half_width]);
        barrier();
    }
    if (lane == 0u) grids[2u * nodes] = vec4(largest[0], 0.0, 0.0, 0.0);
}
