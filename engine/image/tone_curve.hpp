// The display transform of the PNG preview: ACES filmic curve, sRGB encoding, 8-bit rounding.
// Header-only so the curve can be unit-tested at known points.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>

namespace vkw {

// Narkowicz 2015 fit of the ACES filmic curve, clamped to [0, 1]. NaN stays NaN (the caller
// decides how to show it).
inline float aces_narkowicz(float x) {
    // The fit is only meaningful for x >= 0: for x < -0.012 its numerator turns positive again
    // and negative radiance would display as bright.
    if (x <= 0.0f) return 0.0f;
    // Past x ~ 7.24 the fit exceeds 1 and is clamped anyway; stopping early keeps x*x from
    // overflowing to inf/inf = NaN for huge (or infinite) inputs.
    if (x > 1.0e4f) return 1.0f;
    constexpr float a = 2.51f, b = 0.03f, c = 2.43f, d = 0.59f, e = 0.14f;
    return std::clamp((x * (a * x + b)) / (x * (c * x + d) + e), 0.0f, 1.0f);
}

// The piecewise sRGB transfer function (IEC 61966-2-1), input clamped to [0, 1].
inline float linear_to_srgb(float x) {
    x = std::clamp(x, 0.0f, 1.0f);
    return x <= 0.0031308f ? 12.92f * x : 1.055f * std::pow(x, 1.0f / 2.4f) - 0.055f;
}

// Rounds an encoded value in [0, 1] to the nearest 8-bit level.
inline std::uint8_t to_unorm8(float encoded) {
    return static_cast<std::uint8_t>(std::lround(std::clamp(encoded, 0.0f, 1.0f) * 255.0f));
}

// The whole chain for one finite channel value already multiplied by the exposure.
inline std::uint8_t tonemap_to_srgb8(float exposed_linear) {
    return to_unorm8(linear_to_srgb(aces_narkowicz(exposed_linear)));
}

}  // namespace vkw
