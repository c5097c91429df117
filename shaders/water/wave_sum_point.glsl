// The sum of sine and Gerstner waves (engine/water/wave_sum_surface.hpp) at one grid parameter,
// with analytic tangents: the CPU's formulas in fp32, term by term in the same order. Shared
// by the grid kernel (wave_sum.comp) and the water's per-pixel refinement
// (water/surface_refinement.glsl). The includer defines WATER_WAVES_BINDING, the binding of
// the wave table in set 0.
#ifndef VKWATER_WAVE_SUM_POINT_GLSL
#define VKWATER_WAVE_SUM_POINT_GLSL

// std140 and std430 agree on this layout: 32 bytes per wave (GpuWave in
// passes/water/water_surface_sum.cpp).
struct Wave {
    vec2 k_vector;             // k d, rad/m
    float phase_at_origin;     // radians
    float amplitude;           // A, m
    float displacement_scale;  // steepness / k^2: D = displacement_scale k_vector cos(theta)
    float unused0;
    float unused1;
    float unused2;
};

// A uniform block: every invocation reads the same wave at once, which lavapipe turns into one
// load where a storage buffer costs one per lane (ten times slower here).
layout(set = 0, binding = WATER_WAVES_BINDING, std140) uniform Waves { Wave waves[64]; };  // passes::kMaxGpuWaves

// P(x) = (x0 + Dx, level + h, z0 + Dz) and its tangents dP/dx0, dP/dz0.
void wave_sum_point(vec2 x, float level, uint wave_count, out vec3 position, out vec3 dP_du, out vec3 dP_dv) {
    position = vec3(x.x, level, x.y);
    dP_du = vec3(1.0, 0.0, 0.0);
    dP_dv = vec3(0.0, 0.0, 1.0);
    for (uint w = 0; w < wave_count; ++w) {
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
}

#endif
