// The mean CIE L*u*v* distance against answers computed by hand. For greys u* = v* = 0 (a grey's
// chromaticity is the white's), so the distance is |L*(Y1) - L*(Y2)| with
// L*(Y) = 116 Y^(1/3) - 16 above (6/29)^3 and (29/3)^3 Y below, Y the exposed grey level.
#include <gtest/gtest.h>

#include <cmath>

#include "engine/core/errors.hpp"
#include "tests/metrics/metrics_test_support.hpp"
#include "tools/metrics/metrics.hpp"

namespace vkw {
namespace {

using metrics::luv_mean_distance;
using metrics::rgb_view;
using test::expect_relative;

double luv(const ImageRGBA32F& a, const ImageRGBA32F& b) {
    return luv_mean_distance(rgb_view(a), rgb_view(b), test::all_pixels(b));
}

double lightness_by_hand(double y) {
    return y > std::pow(6.0 / 29.0, 3.0) ? 116.0 * std::cbrt(y) - 16.0 : std::pow(29.0 / 3.0, 3.0) * y;
}

constexpr int kW = 40, kH = 30;

TEST(metrics_luv, IdenticalImagesGiveZero) {
    const ImageRGBA32F b = test::make_image(kW, kH, [](int x, int y) {
        return test::Rgb{0.05f * static_cast<float>(x), 0.5f, 0.02f * static_cast<float>(y)};
    });
    EXPECT_EQ(luv(b, b), 0.0);
}

TEST(metrics_luv, ConstantOffsetOfGreys) {
    // Reference grey 0.5: exposure 0.18 / 0.5 = 0.36. Test 0.6 (0.5 + 0.1) exposes to 0.216.
    const ImageRGBA32F b = test::grey_image(kW, kH, 0.5f);
    const double exposure = 0.18 / 0.5;
    const double a_level = static_cast<double>(0.5f + 0.1f) * exposure;
    expect_relative(luv(test::offset(b, 0.1f), b), lightness_by_hand(a_level) - lightness_by_hand(0.18));
}

TEST(metrics_luv, UniformScaleOfGreys) {
    // Any reference grey exposes to 0.18; the test, twice as bright, to 0.36.
    const ImageRGBA32F b = test::grey_image(kW, kH, 3.0f);
    expect_relative(luv(test::scaled(b, 2.0f), b), lightness_by_hand(0.36) - lightness_by_hand(0.18));
    // A hundredth of it exposes to 0.0018, below (6/29)^3 = 0.008856: the linear segment.
    expect_relative(luv(test::scaled(b, 0.01f), b),
                    lightness_by_hand(0.18) - lightness_by_hand(static_cast<double>(3.0f * 0.01f) * 0.06));
}

TEST(metrics_luv, ExposedValuesAreClampedToOne) {
    // Ten times the reference exposes to 1.8, clamped to 1: L* = 100.
    const ImageRGBA32F b = test::grey_image(kW, kH, 0.7f);
    expect_relative(luv(test::scaled(b, 10.0f), b), 100.0 - lightness_by_hand(0.18));
}

TEST(metrics_luv, SinglePixelSpikeIsAveragedOverAllPixels) {
    // Reference 0.18 everywhere (exposure 1); one test pixel at 100 clamps to L* = 100.
    const ImageRGBA32F b = test::grey_image(kW, kH, 0.18f);
    const double grey = static_cast<double>(0.18f);
    expect_relative(luv(test::with_pixel(b, 7, 5, {100.0f, 100.0f, 100.0f}), b),
                    (100.0 - lightness_by_hand(grey * (0.18 / grey))) / (kW * kH));
}

TEST(metrics_luv, RedAgainstMiddleGreyMatchesPublishedValues) {
    // sRGB red (1, 0, 0) in CIE L*u*v* (D65): (53.2408, 175.0151, 37.7564) (Lindbloom's
    // calculator, 4 decimals); the grey 0.18 is (49.4961, 0, 0). Only the L*u*v* coordinates are
    // taken from a table here, hence the looser tolerance.
    const ImageRGBA32F b = test::grey_image(1, 1, 0.18f);
    const double expected =
        std::sqrt(std::pow(53.2408 - lightness_by_hand(0.18), 2.0) + std::pow(175.0151, 2.0) + std::pow(37.7564, 2.0));
    EXPECT_NEAR(luv(test::constant_image(1, 1, {1.0f, 0.0f, 0.0f}), b), expected, 0.01);
}

TEST(metrics_luv, MaskSetsTheExposureAndTheAverage) {
    // Only the right half (grey 2) counts: exposure 0.09; the test doubles it there: 0.36.
    const ImageRGBA32F b = test::make_image(kW, kH, [](int x, int) {
        const float v = x < kW / 2 ? 0.5f : 2.0f;
        return test::Rgb{v, v, v};
    });
    const ImageRGBA32F a = test::make_image(kW, kH, [](int x, int) {
        const float v = x < kW / 2 ? 50.0f : 4.0f;
        return test::Rgb{v, v, v};
    });
    const ImageRGBA32F mask = test::make_image(kW, kH, [](int x, int) {
        return test::Rgb{x < kW / 2 ? 0.0f : 1.0f, 0.0f, 0.0f};
    });
    expect_relative(luv_mean_distance(rgb_view(a), rgb_view(b), metrics::counted_pixels(kW, kH, &mask)),
                    lightness_by_hand(0.36) - lightness_by_hand(0.18));
}

TEST(metrics_luv, BlackReferenceIsAUserError) {
    EXPECT_THROW(luv(test::grey_image(kW, kH, 1.0f), test::grey_image(kW, kH, 0.0f)), UserError);
}

}  // namespace
}  // namespace vkw
