#version 460
// Scatter only, 64-bit fixed point (tools/benchmarks/caustics_bench.cpp): the photon pass's 12
// uint64 atomicAdd per photon into a flux buffer of the same layout (three uint64 per texel, row
// after row), without tracing. Each photon deposits 2^20 units split as caustic_photons.comp
// splits its flux.
#extension GL_GOOGLE_include_directive : require
#extension GL_EXT_shader_explicit_arithmetic_types_int64 : require
#extension GL_EXT_shader_atomic_int64 : require

#include "caustics/bench/caustic_scatter.glsl"

layout(set = 0, binding = 0, std430) buffer Flux { uint64_t flux[]; };

void deposit(ivec2 texel, uint channel, uint64_t q) {
    if (q == 0ul || !scatter_on_map(texel)) return;
    atomicAdd(flux[(uint(texel.y) * pc.width + uint(texel.x)) * 3u + channel], q);
}

uint64_t share(uint64_t q, float w) { return min(uint64_t(float(q) * w + 0.5), q); }

void main() {
    ivec2 t0;
    vec2 f;
    if (!scatter_photon(t0, f)) return;
    for (uint ch = 0u; ch < 3u; ++ch) {
        const uint64_t total = uint64_t(1u << 20);
        const uint64_t x0 = share(total, 1.0 - f.x), x1 = total - x0;
        const uint64_t x0y0 = share(x0, 1.0 - f.y), x1y0 = share(x1, 1.0 - f.y);
        deposit(t0, ch, x0y0);
        deposit(t0 + ivec2(0, 1), ch, x0 - x0y0);
        deposit(t0 + ivec2(1, 0), ch, x1y0);
        deposit(t0 + ivec2(1, 1), ch, x1 - x1y0);
    }
}
