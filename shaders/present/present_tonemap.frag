#version 450
// The window's display transform (passes/present/present_tonemap.hpp): exposure, the ACES filmic curve
// (Narkowicz 2015 fit) and the sRGB encoding, exactly the chain of engine/image/tone_curve.hpp.

layout(binding = 0) uniform sampler2D hdr;
layout(push_constant) uniform Push {
    float exposure;
    uint encode_srgb;  // 0 when the target's _SRGB format encodes
} push;

layout(location = 0) out vec4 out_colour;

// tone_curve.hpp's aces_narkowicz: 0 for x <= 0 (the fit turns up again below -0.012), 1 past
// 1e4 (x * x would overflow), clamped to [0, 1].
float aces_narkowicz(float x) {
    if (x <= 0.0) return 0.0;
    if (x > 1.0e4) return 1.0;
    const float a = 2.51, b = 0.03, c = 2.43, d = 0.59, e = 0.14;
    return clamp((x * (a * x + b)) / (x * (c * x + d) + e), 0.0, 1.0);
}

// The piecewise sRGB transfer function (IEC 61966-2-1).
float linear_to_srgb(float x) {
    x = clamp(x, 0.0, 1.0);
    return x <= 0.0031308 ? 12.92 * x : 1.055 * pow(x, 1.0 / 2.4) - 0.055;
}

void main() {
    // One texel per pixel: the HDR image has the swapchain's size.
    const vec3 radiance = texelFetch(hdr, ivec2(gl_FragCoord.xy), 0).rgb;
    if (any(isnan(radiance)) || any(isinf(radiance))) {
        out_colour = vec4(1.0, 0.0, 1.0, 1.0);  // magenta, as the PNG preview draws them
        return;
    }
    vec3 display;
    for (int c = 0; c < 3; ++c) {
        const float curve = aces_narkowicz(radiance[c] * push.exposure);
        display[c] = push.encode_srgb != 0u ? linear_to_srgb(curve) : curve;
    }
    out_colour = vec4(display, 1.0);
}
