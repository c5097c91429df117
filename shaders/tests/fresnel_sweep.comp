#version 450
#extension GL_GOOGLE_include_directive : require
// Test kernel: evaluates shaders/common/fresnel.glsl from both sides of the interface.
// Samples i < count use cos_i = i / (count - 1); the next 7 use the cosines in
// `table_cos` (the angles docs/model.md tabulates). Output per sample, 10 floats:
// cos_i as used, (R, T) exact from air, (R, T) exact from water,
// (R, T) Schlick from air, (R, T) Schlick from water, and a zero.
#include "common/fresnel.glsl"

layout(local_size_x = 64) in;
layout(set = 0, binding = 0, std430) writeonly buffer Results { float values[]; } results;
layout(push_constant) uniform Params {
    float ior;
    uint count;
    float table_cos[7];
} params;

void main() {
    uint i = gl_GlobalInvocationID.x;
    if (i >= params.count + 7) return;
    float cos_i = i < params.count ? float(i) / float(params.count - 1) : params.table_cos[i - params.count];
    Fresnel from_air = fresnel_exact(cos_i, 1.0, params.ior);
    Fresnel from_water = fresnel_exact(cos_i, params.ior, 1.0);
    Fresnel schlick_air = fresnel_schlick(cos_i, 1.0, params.ior);
    Fresnel schlick_water = fresnel_schlick(cos_i, params.ior, 1.0);
    float out_values[10] = float[](cos_i, from_air.R, from_air.T, from_water.R, from_water.T,
                                   schlick_air.R, schlick_air.T, schlick_water.R, schlick_water.T, 0.0);
    for (int k = 0; k < 10; ++k) results.values[10 * i + k] = out_values[k];
}
