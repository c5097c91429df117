// Box downsampling and the errors at reduced resolution: light moved inside a 4x4 block
// vanishes, a block's energy change stays, hand-computed from the relMSE definition
// (tools/metrics/metrics.hpp). Tolerances: test::kRelativeTolerance (metrics_test_support.hpp).
#include <gtest/gtest.h>

#include <functional>
#include <string>

#include "engine/core/errors.hpp"
#include "tests/metrics/metrics_test_support.hpp"
#include "tools/metrics/downsample.hpp"
#include "tools/metrics/metrics.hpp"

namespace vkw {
namespace {

using metrics::box_downsample;
using metrics::compare_images;

constexpr int kFactor = metrics::kBenchDownsampleFactor;  // 4
constexpr int kSide = 2 * kFactor;                        // 8x8 pixels: 2x2 blocks

TEST(metrics_downsample, BlockMeansOfEveryChannelAndLayer) {
    // Pixel (x, y) holds x + 10 y in R, 2 in G, y in B, x in alpha; the layer holds 3x + y.
    ImageRGBA32F image = test::make_image(kSide, kSide, [](int x, int y) {
        return test::Rgb{static_cast<float>(x + 10 * y), 2.0f, static_cast<float>(y)};
    });
    for (int y = 0; y < kSide; ++y) {
        for (int x = 0; x < kSide; ++x) image.pixel(x, y)[3] = static_cast<float>(x);
    }
    ExtraLayer layer{"caustic", {}};
    for (int y = 0; y < kSide; ++y) {
        for (int x = 0; x < kSide; ++x) layer.rgb.insert(layer.rgb.end(), 3, static_cast<float>(3 * x + y));
    }
    image.layers.push_back(layer);
    const ImageRGBA32F small = box_downsample(image, kFactor);
    ASSERT_EQ(small.width, 2);
    ASSERT_EQ(small.height, 2);
    ASSERT_EQ(small.layers.size(), 1u);
    // The mean of x over a block's columns 4bx..4bx+3 is 4bx + 1.5 (and alike for y); every
    // value is a small integer or half-integer, exact in float, so the means are exact.
    for (int by = 0; by < 2; ++by) {
        for (int bx = 0; bx < 2; ++bx) {
            const float mx = 4.0f * static_cast<float>(bx) + 1.5f, my = 4.0f * static_cast<float>(by) + 1.5f;
            const float* p = small.pixel(bx, by);
            EXPECT_EQ(p[0], mx + 10.0f * my);
            EXPECT_EQ(p[1], 2.0f);
            EXPECT_EQ(p[2], my);
            EXPECT_EQ(p[3], mx);
            EXPECT_EQ(small.layers[0].rgb[static_cast<size_t>(by * 2 + bx) * 3], 3.0f * mx + my);
        }
    }
    EXPECT_EQ(small.layers[0].name, "caustic");
}

TEST(metrics_downsample, PartialBlocksAtTheEdgesAreLeftOut) {
    // 10x9 by 4: 2x2 blocks; columns 8-9 and row 8 belong to no whole block.
    ImageRGBA32F image = test::make_image(10, 9, [](int x, int y) {
        const float v = x >= 8 || y >= 8 ? 1000.0f : 1.0f;
        return test::Rgb{v, v, v};
    });
    const ImageRGBA32F small = box_downsample(image, kFactor);
    EXPECT_EQ(small.width, 2);
    EXPECT_EQ(small.height, 2);
    for (size_t i = 0; i < small.rgba.size(); ++i) EXPECT_EQ(small.rgba[i], 1.0f) << i;
}

TEST(metrics_downsample, FactorOneIsTheImage) {
    const ImageRGBA32F image = test::make_image(5, 3, [](int x, int y) {
        return test::Rgb{0.1f * static_cast<float>(x), 0.7f, 0.3f * static_cast<float>(y)};
    });
    EXPECT_EQ(box_downsample(image, 1).rgba, image.rgba);
}

TEST(metrics_downsample, FactorOutOfRangeNamesTheAcceptedRange) {
    const ImageRGBA32F image = test::grey_image(kSide, 5, 1.0f);
    for (int factor : {0, 6}) {
        const std::string message = test::user_error_message([&] { box_downsample(image, factor); });
        EXPECT_NE(message.find("factor " + std::to_string(factor)), std::string::npos) << message;
        EXPECT_NE(message.find("accepted: 1 to 5"), std::string::npos) << message;
    }
}

TEST(metrics_downsample, LightMovedInsideABlockVanishes) {
    // Grey 1 with a spike of 5 at (1, 1); the test has the spike at (2, 3) instead, the same
    // 4x4 block. Full resolution: s = mean = (63 + 5) / 64; two pixels differ in 3 channels
    // each, n = 192 values, none dropped (192 / 1000 = 0):
    //   relMSE = 3 [ (4/s)^2 / ((5/s)^2 + 0.01) + (4/s)^2 / ((1/s)^2 + 0.01) ] / 192.
    // Downsampled, both blocks hold (15 + 5) / 16 in either image: every term is 0.
    const ImageRGBA32F reference = test::with_pixel(test::grey_image(kSide, kSide, 1.0f), 1, 1, {5, 5, 5});
    const ImageRGBA32F moved = test::with_pixel(test::grey_image(kSide, kSide, 1.0f), 2, 3, {5, 5, 5});
    const double s = 68.0 / 64.0, d = 4.0 / s;
    const double expected = 3.0 * (d * d / (25.0 / (s * s) + 0.01) + d * d / (1.0 / (s * s) + 0.01)) / 192.0;
    test::expect_relative(compare_images(moved, reference).rel_mse, expected);
    const metrics::Metrics small = compare_images(box_downsample(moved, kFactor), box_downsample(reference, kFactor));
    EXPECT_EQ(small.rel_mse, 0.0);
    EXPECT_EQ(small.flip_mean, 0.0);
    EXPECT_EQ(small.bias, 0.0);
}

TEST(metrics_downsample, ABlocksEnergyChangeStays) {
    // Grey 1; the test's top-left block is 1.5. Full resolution: s = 1, 16 of 64 pixels differ
    // by 0.5 in 3 channels: relMSE = 48 (0.25 / 1.01) / 192 = 0.0625 / 1.01. Downsampled: 1 of
    // 4 blocks differs by 0.5: 3 (0.25 / 1.01) / 12, the same number: nothing vanishes.
    const ImageRGBA32F reference = test::grey_image(kSide, kSide, 1.0f);
    const ImageRGBA32F brighter = test::make_image(kSide, kSide, [](int x, int y) {
        const float v = x < kFactor && y < kFactor ? 1.5f : 1.0f;
        return test::Rgb{v, v, v};
    });
    test::expect_relative(compare_images(brighter, reference).rel_mse, 0.0625 / 1.01);
    const metrics::Metrics small =
        compare_images(box_downsample(brighter, kFactor), box_downsample(reference, kFactor));
    test::expect_relative(small.rel_mse, 0.0625 / 1.01);
    // The energy: the mean rises by 0.5 on a quarter of the image either way.
    test::expect_relative(small.bias, 0.125);
}

TEST(metrics_downsample, MaskBlockCountsOnlyWhenWhollySelected) {
    // Every pixel selected but (5, 1), in the top-right block: that block is left out.
    const ImageRGBA32F mask = test::with_pixel(test::grey_image(kSide, kSide, 1.0f), 5, 1, {0, 0, 0});
    const ImageRGBA32F small = metrics::box_downsample_mask(mask, kFactor);
    ASSERT_EQ(small.width, 2);
    EXPECT_EQ(small.pixel(0, 0)[0], 1.0f);
    EXPECT_EQ(small.pixel(1, 0)[0], 0.0f);
    EXPECT_EQ(small.pixel(0, 1)[0], 1.0f);
    EXPECT_EQ(small.pixel(1, 1)[0], 1.0f);
}

}  // namespace
}  // namespace vkw
