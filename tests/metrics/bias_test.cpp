// The signed mean bias mean(a) / mean(b) - 1 against answers computed by hand.
#include <gtest/gtest.h>

#include "engine/core/errors.hpp"
#include "tests/metrics/metrics_test_support.hpp"
#include "tools/metrics/metrics.hpp"

namespace vkw {
namespace {

using metrics::mean_bias;
using metrics::rgb_view;
using test::expect_relative;

double bias(const ImageRGBA32F& a, const ImageRGBA32F& b) {
    return mean_bias(rgb_view(a), rgb_view(b), test::all_pixels(b));
}

constexpr int kW = 40, kH = 30;

// Even columns 1, odd columns 3: mean 2.
ImageRGBA32F two_level() {
    return test::make_image(kW, kH, [](int x, int) {
        const float v = x % 2 == 0 ? 1.0f : 3.0f;
        return test::Rgb{v, v, v};
    });
}

TEST(metrics_bias, IdenticalImagesGiveZero) {
    const ImageRGBA32F b = two_level();
    EXPECT_EQ(bias(b, b), 0.0);
}

TEST(metrics_bias, UniformScaleGivesExactlyKMinusOne) {
    // Every value (1, 3, 1.5, 4.5, 0.5, 1.5) and every partial sum of 3600 of them is a multiple
    // of 0.5 below 2^52: the sums are exact, so the ratio is exactly k.
    const ImageRGBA32F b = two_level();
    EXPECT_EQ(bias(test::scaled(b, 1.5f), b), 0.5);
    EXPECT_EQ(bias(test::scaled(b, 0.5f), b), -0.5);
}

TEST(metrics_bias, ConstantOffset) {
    // mean(b) = 2, mean(a) = 2.25: exactly 0.125.
    const ImageRGBA32F b = two_level();
    EXPECT_EQ(bias(test::offset(b, 0.25f), b), 0.125);
}

TEST(metrics_bias, SinglePixelSpikeIsNotDropped) {
    // One pixel 1 -> 100 in all 3 channels: sum(a) = 3600 + 3 * 99, bias = 297 / 3600.
    const ImageRGBA32F b = test::grey_image(kW, kH, 1.0f);
    expect_relative(bias(test::with_pixel(b, 7, 5, {100.0f, 100.0f, 100.0f}), b), 297.0 / 3600.0);
}

TEST(metrics_bias, MaskRestrictsBothMeans) {
    // Mask keeps the odd columns (b = 3); the test doubles only them: bias 1 exactly.
    const ImageRGBA32F b = two_level();
    const ImageRGBA32F a = test::make_image(kW, kH, [](int x, int) {
        const float v = x % 2 == 0 ? 7.0f : 6.0f;
        return test::Rgb{v, v, v};
    });
    const ImageRGBA32F mask = test::make_image(kW, kH, [](int x, int) {
        return test::Rgb{x % 2 == 0 ? 0.5f : 0.51f, 0.0f, 0.0f};  // R > 0.5 counts; exactly 0.5 does not
    });
    EXPECT_EQ(mean_bias(rgb_view(a), rgb_view(b), metrics::counted_pixels(kW, kH, &mask)), 1.0);
}

TEST(metrics_bias, BlackReferenceIsAUserError) {
    EXPECT_THROW(bias(test::grey_image(kW, kH, 1.0f), test::grey_image(kW, kH, 0.0f)), UserError);
}

}  // namespace
}  // namespace vkw
