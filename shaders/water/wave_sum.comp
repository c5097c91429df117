#version 450
#extension GL_GOOGLE_include_directive : require
// The sum of sine and Gerstner waves (engine/water/wave_sum_surface.hpp) at every vertex of
// the water grid, with analytic tangents: the CPU's formulas in fp32, term by term in the
// same order. Flat water is this kernel with no waves. The per-wave constants, including the
// phase at the origin -w t + p (reduced to [-pi, pi] in double on the CPU, so that the time
// costs no precision here), come from passes/water/water_surface_sum.cpp in a uniform buffer of
// kMaxGpuWaves (64) entries: every invocation reads the same wave at once, which lavapipe
// turns into one load where a storage buffer costs one per lane (ten times slower here).
#include "water/water_grid_invocation.glsl"

layout(local_size_x = 8, local_size_y = 8) in;

// std140 and std430 agree on this layout: 32 bytes per wave.
struct Wave {
    vec2 k_vector;             // k d, rad/m
    float phase_at_origin;     // radians
    float amplitude;           // A, m
    float displacement_scale;  // steepness / k^2: D = displacement_scale k_vector cos(theta)
    float unused0;
    float unused1;
    float unused2;
};

layout(set = 0, binding = 0, std140) uniform Waves { Wave waves[64]; };  // passes::kMaxGpuWaves
layout(set = 0, binding = 1, std430) writeonly buffer Vertices { WaterVertex vertices[]; };
layout(push_constant) uniform Params {
    WaterGrid grid;
    uint wave_count;
} params;

void main() {
    uvec2 ij;
    uint slot;
    if (!water_vertex_of_invocation(params.grid, ij, slot)) return;
    const vec2 x = water_grid_parameter(ij, params.grid);
    vec3 position = vec3(x.x, params.grid.level, x.y);
    vec3 dP_du = vec3(1.0, 0.0, 0.0);
    vec3 dP_dv = vec3(0.0, 0.0, 1.0);
    for (uint w = 0; w < params.wave_count; ++w) {
        const Wave wave = waves[w];
        const float theta = dot(wave.k_vector, x) + wave.phase_at_origin;
        const float s = sin(theta);
        const float c = cos(theta);
        const float kx = wave.k_vector.x, kz = wave.k_vector.y;
        const float q = wave.displacement_scale;
        position += vec3(q * kx * c, wave.amplitude * s, q * kz * c);
        dP_du += vec3(-q * kx * kx * s, wave.amplitude * kx * c, -q * kx * kz * s);
        dP_dv += vec3(-q * kx * kz * s, wave.amplitude * kz * c, -q * kz * kz * s);
    }
    vertices[slot] = make_water_vertex(position, dP_du, dP_dv);
}
