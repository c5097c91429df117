// Tests of the preview's display transform at known points of the ACES fit and sRGB curve.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "engine/image/tone_curve.hpp"

namespace vkw {
namespace {

constexpr float kFloatEpsilon = std::numeric_limits<float>::epsilon();  // 2^-23

TEST(image_tone_curve, AcesOfZeroIsZero) { EXPECT_EQ(aces_narkowicz(0.0f), 0.0f); }

TEST(image_tone_curve, AcesOfLargeValuesIsOne) {
    EXPECT_EQ(aces_narkowicz(16.0f), 1.0f);  // the fit crosses 1 near x = 7.24, then clamps
    EXPECT_EQ(aces_narkowicz(1.0e6f), 1.0f);
    EXPECT_EQ(aces_narkowicz(std::numeric_limits<float>::max()), 1.0f);
    EXPECT_EQ(aces_narkowicz(std::numeric_limits<float>::infinity()), 1.0f);
    EXPECT_GT(aces_narkowicz(4.0f), 0.95f);
    EXPECT_LT(aces_narkowicz(4.0f), 1.0f);
}

TEST(image_tone_curve, AcesOfNegativeIsZero) {
    // The unclamped fit gives 1.25 at x = -1; negative radiance must not show as white.
    EXPECT_EQ(aces_narkowicz(-1.0f), 0.0f);
    EXPECT_EQ(aces_narkowicz(-1.0e30f), 0.0f);
}

TEST(image_tone_curve, AcesAtMiddleGreyMatchesHandComputation) {
    // By hand, exactly in decimal:
    //   numerator   = 0.18 * (2.51 * 0.18 + 0.03)        = 0.18 * 0.4818        = 0.086724
    //   denominator = 0.18 * (2.43 * 0.18 + 0.59) + 0.14 = 0.18 * 1.0274 + 0.14 = 0.324932
    //   ratio       = 0.086724 / 0.324932                = 0.26689892038949686...
    const double expected = 0.086724 / 0.324932;
    // Float evaluation rounds 6 decimal constants (0.18, 2.51, 0.03, 2.43, 0.59, 0.14) and 8
    // arithmetic results, each with relative error <= 2^-24. All terms are positive (no
    // cancellation), so each error reaches the result scaled by at most 1, except the one in x
    // (d ln f / d ln x = 1.13 at 0.18): in total < 14.2 * 2^-24 ~ 7.1 * FLT_EPSILON; allow 8.
    const double tolerance = expected * 8.0 * kFloatEpsilon;
    EXPECT_NEAR(aces_narkowicz(0.18f), expected, tolerance);
}

TEST(image_tone_curve, SrgbEndpoints) {
    EXPECT_EQ(linear_to_srgb(0.0f), 0.0f);
    // 1.055f - 0.055f is one float step below 1.
    EXPECT_NEAR(linear_to_srgb(1.0f), 1.0f, kFloatEpsilon);
    EXPECT_EQ(linear_to_srgb(-1.0f), 0.0f);
    EXPECT_NEAR(linear_to_srgb(2.0f), 1.0f, kFloatEpsilon);
}

TEST(image_tone_curve, SrgbAtTheKnee) {
    const float knee = 0.0031308f;
    // At and below the knee the linear segment applies: 12.92 * 0.0031308 = 0.040449936
    // (one product, rounded once, plus the rounding of the two constants: 3 ulp at most).
    EXPECT_NEAR(linear_to_srgb(knee), 0.040449936, 0.040449936 * 3.0 * kFloatEpsilon);
    EXPECT_NEAR(linear_to_srgb(knee / 2.0f), 0.040449936 / 2.0, 0.040449936 * 3.0 * kFloatEpsilon);
    // Just above it the power segment applies; the two segments of the standard meet to within
    // 3e-8 there (1.055 * 0.0031308^(1/2.4) - 0.055 = 0.0404499075), far below one 8-bit step.
    const float above = std::nextafter(knee, 1.0f);
    EXPECT_NEAR(linear_to_srgb(above), 0.040449936, 1.0e-6);
}

TEST(image_tone_curve, EightBitEncodingRoundsToNearest) {
    EXPECT_EQ(tonemap_to_srgb8(0.0f), 0);
    EXPECT_EQ(tonemap_to_srgb8(1.0e6f), 255);
    EXPECT_EQ(to_unorm8(0.5f / 255.0f - 1.0e-4f), 0);
    EXPECT_EQ(to_unorm8(0.5f / 255.0f + 1.0e-4f), 1);
    EXPECT_EQ(to_unorm8(1.0f), 255);
}

}  // namespace
}  // namespace vkw
