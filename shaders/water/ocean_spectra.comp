#version 450
#extension GL_GOOGLE_include_directive : require
// The FFT ocean's spectra at time t (engine/water/fft_ocean.hpp):
//   h~(k, t) = h0(k) exp(i w t) + conj(h0(-k)) exp(-i w t),  w = sqrt(g |k|),
// times each field's multiplier m_f(k). Two real fields share one complex plane,
//   plane p = m_{2p} h~ + i m_{2p+1} h~,  p = 0..3,
// because each m_f h~ is Hermitian (m_f(-k) h~(-k) = conj(m_f(k) h~(k))): the inverse FFT
// of a plane is then field 2p in its real part and field 2p + 1 in its imaginary part, so
// four transforms give the eight fields where the CPU runs eight. Planes 2q and 2q + 1 share
// the vec4 elements of grid q (xy and zw), which the FFT transforms together.
// h0 is the CPU's double-precision spectrum rounded to fp32 (passes/water/water_surface_spectrum.hpp).
#include "water/complex.glsl"
#include "water/ocean_modes.glsl"

layout(local_size_x = 8, local_size_y = 8) in;

layout(set = 0, binding = 0, std430) readonly buffer InitialSpectrum { vec2 h0[]; };
layout(set = 0, binding = 1, std430) writeonly buffer Grids { vec4 grids[]; };
layout(push_constant) uniform Params {
    uint n;
    float dk;  // 2 pi / patch_size, rad/m
    float time;
    float choppiness;
} params;

void main() {
    const uvec2 ab = gl_GlobalInvocationID.xy;
    const uint n = params.n;
    if (ab.x >= n || ab.y >= n) return;
    const uint index = ab.y * n + ab.x;
    // The index of -k: (n - a) mod n, (n - b) mod n, with n a power of two.
    const uint opposite = ((n - ab.y) & (n - 1)) * n + ((n - ab.x) & (n - 1));
    const vec2 k = ocean_wave_vector(ab, n, params.dk);
    const vec2 rotation = complex_exp_i(ocean_angular_frequency(k) * params.time);
    const vec2 h = complex_mul(h0[index], rotation) +
                   complex_mul(complex_conj(h0[opposite]), complex_conj(rotation));
    vec2 m[kOceanFieldCount];
    ocean_field_multipliers(k, params.choppiness, m);
    vec2 planes[kOceanFieldCount / 2];
    for (uint p = 0; p < kOceanFieldCount / 2; ++p) {
        planes[p] = complex_mul(m[2 * p] + complex_times_i(m[2 * p + 1]), h);
    }
    grids[index] = vec4(planes[0], planes[1]);
    grids[n * n + index] = vec4(planes[2], planes[3]);
}
