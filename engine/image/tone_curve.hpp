// The display transform of the PNG preview: ACES filmic curve, sRGB encoding, 8-bit rounding
// (with a dither, for the preview file). Header-only so the curve can be unit-tested at known points.
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

// Chris Wellons' "lowbias32" integer hash: every input bit changes about half the output bits.
inline std::uint32_t dither_hash(std::uint32_t x) {
    x ^= x >> 16;
    x *= 0x7feb352du;
    x ^= x >> 15;
    x *= 0x846ca68bu;
    x ^= x >> 16;
    return x;
}

// The preview's dither at pixel (x, y), channel c, in 8-bit levels: the difference of two uniform
// values from one hash of the three, so triangular on (-1, 1). A triangular dither of this width
// makes the quantiser's error independent of the signal and its mean zero: a smooth gradient's
// local average keeps its true value instead of stepping in bands, and the noise does not change
// with the level. Keyed by the coordinates, so the same image gives the same bytes every time.
inline float preview_dither(std::uint32_t x, std::uint32_t y, std::uint32_t c) {
    const std::uint32_t h = dither_hash(x * 0x9e3779b9u ^ dither_hash(y * 0x85ebca6bu ^ dither_hash(c + 1u)));
    const float u1 = (static_cast<float>(h >> 16) + 0.5f) / 65536.0f;
    const float u2 = (static_cast<float>(h & 0xffffu) + 0.5f) / 65536.0f;
    return u1 - u2;
}

// An encoded value in [0, 1] rounded to 8 bits after the dither: within one level of to_unorm8's
// (|dither| < 1). Black and white (0 and 1, where the tone curve clamps) stay exact.
inline std::uint8_t to_unorm8_dithered(float encoded, std::uint32_t x, std::uint32_t y, std::uint32_t c) {
    if (!(encoded > 0.0f)) return 0;
    if (encoded >= 1.0f) return 255;
    return static_cast<std::uint8_t>(std::lround(std::clamp(encoded * 255.0f + preview_dither(x, y, c), 0.0f, 255.0f)));
}

}  // namespace vkw
