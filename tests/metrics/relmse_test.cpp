// relMSE against answers computed by hand from its definition (tools/metrics/metrics.hpp):
// s = mean(b); e = (a/s - b/s)^2 / ((b/s)^2 + 0.01); the n / 1000 largest e dropped; mean of the rest.
#include <gtest/gtest.h>

#include <limits>

#include "engine/core/errors.hpp"
#include "tests/metrics/metrics_test_support.hpp"
#include "tools/metrics/metrics.hpp"

namespace vkw {
namespace {

using metrics::rel_mse;
using metrics::rgb_view;
using test::expect_relative;

double relmse(const ImageRGBA32F& a, const ImageRGBA32F& b) {
    return rel_mse(rgb_view(a), rgb_view(b), test::all_pixels(b));
}

// 40 x 30 pixels = 3600 values, so floor(0.001 * 3600) = 3 values are dropped.
constexpr int kW = 40, kH = 30;
constexpr double kValues = 3.0 * kW * kH;

// Even columns 1, odd columns 3: mean s = 2, so b/s is 0.5 or 1.5, 1800 values each.
ImageRGBA32F two_level() {
    return test::make_image(kW, kH, [](int x, int) {
        const float v = x % 2 == 0 ? 1.0f : 3.0f;
        return test::Rgb{v, v, v};
    });
}

TEST(metrics_relmse, IdenticalImagesGiveZero) {
    const ImageRGBA32F b = test::make_image(kW, kH, [](int x, int y) {
        return test::Rgb{0.1f * static_cast<float>(x), 0.01f * static_cast<float>(y * y), 5.0f};
    });
    EXPECT_EQ(relmse(b, b), 0.0);
}

TEST(metrics_relmse, ConstantOffsetOnConstantReference) {
    // b = 2: s = 2, b/s = 1, a/s = 1.25: every e = 0.25^2 / 1.01; dropping 3 equal values
    // leaves the same mean.
    const ImageRGBA32F b = test::grey_image(kW, kH, 2.0f);
    expect_relative(relmse(test::offset(b, 0.5f), b), 0.0625 / 1.01);
}

TEST(metrics_relmse, ConstantOffsetOnTwoLevelReference) {
    // a - b = 0.5, so a/s - b/s = 0.25 everywhere:
    //   b/s = 0.5: e = 0.0625 / 0.26 (the larger: 3 of these 1800 are dropped)
    //   b/s = 1.5: e = 0.0625 / 2.26
    const double large = 0.0625 / 0.26, small = 0.0625 / 2.26;
    const ImageRGBA32F b = two_level();
    expect_relative(relmse(test::offset(b, 0.5f), b), (1797.0 * large + 1800.0 * small) / (kValues - 3.0));
}

TEST(metrics_relmse, UniformScale) {
    // a = 1.5 b: a/s - b/s = 0.5 b/s, e = 0.25 (b/s)^2 / ((b/s)^2 + 0.01):
    //   b/s = 0.5: 0.0625 / 0.26 = 0.2404;  b/s = 1.5: 0.5625 / 2.26 = 0.2489 (dropped 3 times)
    const double at_half = 0.0625 / 0.26, at_one_and_half = 0.5625 / 2.26;
    const ImageRGBA32F b = two_level();
    expect_relative(relmse(test::scaled(b, 1.5f), b), (1800.0 * at_half + 1797.0 * at_one_and_half) / (kValues - 3.0));
    // On a constant reference every value has the same e = (k - 1)^2 / 1.01.
    const ImageRGBA32F grey = test::grey_image(kW, kH, 0.25f);
    expect_relative(relmse(test::scaled(grey, 3.0f), grey), 4.0 / 1.01);
}

TEST(metrics_relmse, SinglePixelSpikeIsDroppedFromLargeImage) {
    // One pixel's 3 values are the 3 largest of 3600: all dropped, the rest agree exactly.
    const ImageRGBA32F b = test::grey_image(kW, kH, 1.0f);
    EXPECT_EQ(relmse(test::with_pixel(b, 7, 5, {100.0f, 100.0f, 100.0f}), b), 0.0);
}

TEST(metrics_relmse, TwoSpikesKeepTheThreeValuesBeyondTheDropped) {
    // 6 spiked values (a/s = 100, b/s = 1, e = 99^2 / 1.01), 3 dropped, 3 kept, out of 3597.
    const ImageRGBA32F b = test::grey_image(kW, kH, 1.0f);
    const ImageRGBA32F a =
        test::with_pixel(test::with_pixel(b, 7, 5, {100.0f, 100.0f, 100.0f}), 30, 20, {100.0f, 100.0f, 100.0f});
    expect_relative(relmse(a, b), 3.0 * 99.0 * 99.0 / 1.01 / (kValues - 3.0));
}

TEST(metrics_relmse, SinglePixelSpikeCountsInSmallImage) {
    // 20 x 10 = 600 values: floor(0.6) = 0 dropped.
    const ImageRGBA32F b = test::grey_image(20, 10, 1.0f);
    expect_relative(relmse(test::with_pixel(b, 3, 4, {100.0f, 100.0f, 100.0f}), b), 3.0 * 99.0 * 99.0 / 1.01 / 600.0);
}

TEST(metrics_relmse, DropCountSwitchesAtOneThousandValues) {
    // One spiked value (R only): 333 pixels = 999 values drop none, 334 = 1002 values drop one.
    const test::Rgb spike{10.0f, 1.0f, 1.0f};
    const ImageRGBA32F b999 = test::grey_image(333, 1, 1.0f);
    expect_relative(relmse(test::with_pixel(b999, 100, 0, spike), b999), 81.0 / 1.01 / 999.0);
    const ImageRGBA32F b1002 = test::grey_image(334, 1, 1.0f);
    EXPECT_EQ(relmse(test::with_pixel(b1002, 100, 0, spike), b1002), 0.0);
}

TEST(metrics_relmse, MaskSelectsPixelsAndTheScale) {
    // Left half 1, right half 3; the mask keeps the right half, so s = 3 and a/s - b/s = 0.1.
    const ImageRGBA32F b = test::make_image(kW, kH, [](int x, int) {
        const float v = x < kW / 2 ? 1.0f : 3.0f;
        return test::Rgb{v, v, v};
    });
    const ImageRGBA32F mask = test::make_image(kW, kH, [](int x, int) {
        const float m = x < kW / 2 ? 0.0f : 1.0f;
        return test::Rgb{m, 0.0f, 0.0f};
    });
    ImageRGBA32F a = test::offset(b, 0.3f);
    a = test::with_pixel(a, 0, 0, {1e6f, 1e6f, 1e6f});  // outside the mask: ignored
    const auto pixels = metrics::counted_pixels(kW, kH, &mask);
    ASSERT_EQ(pixels.size(), static_cast<std::size_t>(kW * kH / 2));
    // 0.3f is not 0.3: use the float offset the images really hold.
    const double d = (static_cast<double>(3.0f + 0.3f) - 3.0) / 3.0;
    expect_relative(rel_mse(rgb_view(a), rgb_view(b), pixels), d * d / 1.01);
}

TEST(metrics_relmse, AlphaIsIgnored) {
    const ImageRGBA32F b = test::grey_image(kW, kH, 1.0f);
    ImageRGBA32F a = b;
    for (std::size_t p = 0; p < a.pixel_count(); ++p) a.rgba[p * 4 + 3] = 0.25f;
    EXPECT_EQ(relmse(a, b), 0.0);
}

TEST(metrics_relmse, BlackReferenceIsAUserError) {
    const ImageRGBA32F b = test::grey_image(kW, kH, 0.0f);
    EXPECT_THROW(relmse(test::grey_image(kW, kH, 1.0f), b), UserError);
}

TEST(metrics_relmse, NonFiniteValuesAreAUserError) {
    const ImageRGBA32F b = test::grey_image(kW, kH, 1.0f);
    const float nan = std::numeric_limits<float>::quiet_NaN();
    EXPECT_THROW(relmse(test::with_pixel(b, 1, 1, {nan, 0.0f, 0.0f}), b), UserError);
    EXPECT_THROW(relmse(b, test::with_pixel(b, 1, 1, {std::numeric_limits<float>::infinity(), 0.0f, 0.0f})), UserError);
}

}  // namespace
}  // namespace vkw
