#version 450
#extension GL_GOOGLE_include_directive : require
// The sum of sine and Gerstner waves (water/wave_sum_point.glsl) at every vertex of the water
// grid. Flat water is this kernel with no waves. The per-wave constants, including the phase
// at the origin -w t + p (reduced to [-pi, pi] in double on the CPU, so that the time costs no
// precision here), come from passes/water/water_surface_sum.cpp in a uniform buffer of
// kMaxGpuWaves (64) entries.
#define WATER_WAVES_BINDING 0
#include "water/water_grid_invocation.glsl"
#include "water/wave_sum_point.glsl"

layout(local_size_x = 8, local_size_y = 8) in;

layout(set = 0, binding = 1, std430) writeonly buffer Vertices { WaterVertex vertices[]; };
layout(push_constant) uniform Params {
    WaterGrid grid;
    uint wave_count;
} params;

void main() {
    uvec2 ij;
    uint slot;
    if (!water_vertex_of_invocation(params.grid, ij, slot)) return;
    vec3 position, dP_du, dP_dv;
    wave_sum_point(water_grid_parameter(ij, params.grid), params.grid.level, params.wave_count, position, dP_du, dP_dv);
    vertices[slot] = make_water_vertex(position, dP_du, dP_dv);
}
