// compare_images / compare_layer: the four metrics together, layers, masks, the exposure range
// and the user errors.
#include <gtest/gtest.h>

#include <functional>
#include <string>

#include "engine/core/errors.hpp"
#include "tests/metrics/metrics_test_support.hpp"
#include "tools/metrics/metrics.hpp"

namespace vkw {
namespace {

using metrics::compare_images;
using metrics::compare_layer;

constexpr int kW = 40, kH = 30;

ImageRGBA32F with_layer(ImageRGBA32F image, const std::string& name, float value) {
    image.layers.push_back(ExtraLayer{name, std::vector<float>(image.pixel_count() * 3, value)});
    return image;
}

TEST(metrics_compare, IdenticalImagesGiveZeroEverywhere) {
    const ImageRGBA32F b = test::make_image(kW, kH, [](int x, int y) {
        return test::Rgb{0.1f + 0.02f * static_cast<float>(x), 0.3f, 0.01f * static_cast<float>(y)};
    });
    const metrics::Metrics m = compare_images(b, b);
    EXPECT_EQ(m.rel_mse, 0.0);
    EXPECT_EQ(m.flip_mean, 0.0);
    EXPECT_EQ(m.bias, 0.0);
    EXPECT_EQ(m.luv_mean, 0.0);
}

TEST(metrics_compare, AgreesWithTheSingleMetrics) {
    const ImageRGBA32F b = test::make_image(kW, kH, [](int x, int y) {
        return test::Rgb{0.1f + 0.02f * static_cast<float>(x), 0.3f, 0.01f * static_cast<float>(y)};
    });
    const ImageRGBA32F a = test::offset(b, 0.05f);
    const auto view_a = metrics::rgb_view(a), view_b = metrics::rgb_view(b);
    const auto pixels = test::all_pixels(b);
    const metrics::Metrics m = compare_images(a, b);
    EXPECT_EQ(m.rel_mse, metrics::rel_mse(view_a, view_b, pixels));
    EXPECT_EQ(m.bias, metrics::mean_bias(view_a, view_b, pixels));
    EXPECT_EQ(m.luv_mean, metrics::luv_mean_distance(view_a, view_b, pixels));
    EXPECT_EQ(m.flip_mean, metrics::flip_mean(view_a, view_b, pixels, metrics::flip_exposure_range(b)));
    EXPECT_GT(m.flip_mean, 0.0);
}

TEST(metrics_compare, GivenExposureRangeIsUsed) {
    const ImageRGBA32F b = test::make_image(kW, kH, [](int x, int) {
        const float v = x == 3 ? 50.0f : 0.2f + 0.01f * static_cast<float>(x);
        return test::Rgb{v, v, v};
    });
    const ImageRGBA32F a = test::scaled(b, 1.3f);
    const metrics::FlipExposureRange range = metrics::flip_exposure_range(b);
    EXPECT_EQ(compare_images(a, b, nullptr, &range).flip_mean, compare_images(a, b).flip_mean);
    const metrics::FlipExposureRange other{5.0, 5.0, 1};  // everything over-exposed to white
    EXPECT_LT(compare_images(a, b, nullptr, &other).flip_mean, compare_images(a, b).flip_mean);
}

TEST(metrics_compare, LayerIsComparedInsteadOfTheMainImage) {
    // Main images identical; the caustic layer is 1.5 against 1: bias 0.5, relMSE 0.25 / 1.01.
    const ImageRGBA32F b = with_layer(test::grey_image(kW, kH, 1.0f), "caustic", 1.0f);
    const ImageRGBA32F a = with_layer(test::grey_image(kW, kH, 1.0f), "caustic", 1.5f);
    EXPECT_EQ(compare_images(a, b).bias, 0.0);
    const metrics::Metrics m = compare_layer(a, b, "caustic");
    EXPECT_EQ(m.bias, 0.5);
    test::expect_relative(m.rel_mse, 0.25 / 1.01);
    const std::string message = test::user_error_message([&] { compare_layer(a, b, "glints"); });
    EXPECT_NE(message.find("'glints'"), std::string::npos) << message;
    EXPECT_NE(message.find("caustic"), std::string::npos) << message;  // lists the layers it has
}

TEST(metrics_compare, SizeMismatchNamesBothSizes) {
    const std::string message = test::user_error_message(
        [] { compare_images(test::grey_image(kW, kH, 1.0f), test::grey_image(20, 10, 1.0f)); });
    EXPECT_NE(message.find("40x30"), std::string::npos) << message;
    EXPECT_NE(message.find("20x10"), std::string::npos) << message;
}

TEST(metrics_compare, MaskErrors) {
    const ImageRGBA32F b = test::grey_image(kW, kH, 1.0f);
    const ImageRGBA32F small_mask = test::grey_image(20, 10, 1.0f);
    const std::string message = test::user_error_message([&] { compare_images(b, b, &small_mask); });
    EXPECT_NE(message.find("20x10"), std::string::npos) << message;
    const ImageRGBA32F empty_mask = test::grey_image(kW, kH, 0.5f);  // R > 0.5 nowhere
    EXPECT_THROW(compare_images(b, b, &empty_mask), UserError);
}

}  // namespace
}  // namespace vkw
