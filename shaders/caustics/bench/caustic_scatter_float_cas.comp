#version 460
// Scatter only, 32-bit float by compare-and-swap (tools/benchmarks/caustics_bench.cpp): the same
// 12 deposits per photon as caustic_scatter_fixed.comp, each a float add done as a CAS loop on
// the value's bits (core Vulkan, no extension), into three floats per texel. Not deterministic:
// float addition depends on the order.
#extension GL_GOOGLE_include_directive : require

#include "caustics/bench/caustic_scatter.glsl"

layout(set = 0, binding = 0, std430) buffer Flux { uint flux[]; };

void deposit_float(ivec2 texel, uint channel, float value) {
    if (!scatter_on_map(texel)) return;
    const uint i = (uint(texel.y) * pc.width + uint(texel.x)) * 3u + channel;
    uint seen = flux[i], expected;
    do {
        expected = seen;
        seen = atomicCompSwap(flux[i], expected, floatBitsToUint(uintBitsToFloat(expected) + value));
    } while (seen != expected);
}

void main() {
    ivec2 t0;
    vec2 f;
    if (scatter_photon(t0, f)) scatter_float_taps(t0, f);
}
