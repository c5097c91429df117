#version 460
// Scatter only, 32-bit float atomicAdd (VK_EXT_shader_atomic_float's
// shaderBufferFloat32AtomicAdd; tools/benchmarks/native_scatter_device.cpp enables it on a device
// of its own): the same 12 deposits per photon as caustic_scatter_fixed.comp, into three floats
// per texel. Not deterministic: float addition depends on the order.
#extension GL_GOOGLE_include_directive : require
#extension GL_EXT_shader_atomic_float : require

#include "caustics/bench/caustic_scatter.glsl"

layout(set = 0, binding = 0, std430) buffer Flux { float flux[]; };

void deposit_float(ivec2 texel, uint channel, float value) {
    if (!scatter_on_map(texel)) return;
    atomicAdd(flux[(uint(texel.y) * pc.width + uint(texel.x)) * 3u + channel], value);
}

void main() {
    ivec2 t0;
    vec2 f;
    if (scatter_photon(t0, f)) scatter_float_taps(t0, f);
}
