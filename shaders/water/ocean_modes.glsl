// The FFT ocean's modes in fp32: the GLSL side of engine/water/fft_ocean.cpp
// (FftOceanSpectrum::frequency and wave_vector, ocean_angular_frequency,
// ocean_field_multipliers), with the fields in the order of its OceanField enum.
#ifndef VKWATER_WATER_OCEAN_MODES_GLSL
#define VKWATER_WATER_OCEAN_MODES_GLSL

#include "water/complex.glsl"

const float kGravity = 9.81;  // engine/water/wave_params.hpp kGravity
const uint kOceanFieldCount = 8;

// The signed frequency of array index i: i for i < n/2, i - n otherwise.
int ocean_frequency(uint index, uint n) {
    return index < n / 2 ? int(index) : int(index) - int(n);
}

// k for the mode at array indices (a, b); dk = 2 pi / patch_size.
vec2 ocean_wave_vector(uvec2 ab, uint n, float dk) {
    return dk * vec2(ocean_frequency(ab.x, n), ocean_frequency(ab.y, n));
}

// Deep-water dispersion w = sqrt(g |k|).
float ocean_angular_frequency(vec2 k) { return sqrt(kGravity * length(k)); }

// m_f(k) for height, Dx, Dz, dh/dx0, dh/dz0, dDx/dx0, dDx/dz0, dDz/dz0 (all zero at k = 0).
void ocean_field_multipliers(vec2 k, float choppiness, out vec2 m[kOceanFieldCount]) {
    for (uint f = 0; f < kOceanFieldCount; ++f) m[f] = vec2(0.0);
    const float len = length(k);
    if (len == 0.0) return;
    const float c = choppiness / len;
    m[0] = vec2(1.0, 0.0);
    m[1] = vec2(0.0, c * k.x);
    m[2] = vec2(0.0, c * k.y);
    m[3] = vec2(0.0, k.x);
    m[4] = vec2(0.0, k.y);
    m[5] = vec2(-c * k.x * k.x, 0.0);
    m[6] = vec2(-c * k.x * k.y, 0.0);
    m[7] = vec2(-c * k.y * k.y, 0.0);
}

#endif
