// The errors `vkwater bench` reports per frame: full and downsampled metrics agree with the
// single metrics on the same images, and the caustic layer's relMSE is a number only when both
// images carry a non-black layer (else "n/a" and why), tested on synthetic images.
#include <gtest/gtest.h>

#include <string>

#include "tests/metrics/metrics_test_support.hpp"
#include "tools/metrics/downsample.hpp"
#include "tools/metrics/reference_errors.hpp"

namespace vkw {
namespace {

constexpr int kW = 40, kH = 32;

ImageRGBA32F with_layer(ImageRGBA32F image, const std::string& name, float value) {
    image.layers.push_back(ExtraLayer{name, std::vector<float>(image.pixel_count() * 3, value)});
    return image;
}

ImageRGBA32F gradient() {
    return test::make_image(kW, kH, [](int x, int y) {
        return test::Rgb{0.1f + 0.02f * static_cast<float>(x), 0.3f, 0.05f + 0.01f * static_cast<float>(y)};
    });
}

TEST(metrics_reference_errors, FullAndDownsampledAgreeWithCompareImages) {
    const ImageRGBA32F reference = gradient();
    const ImageRGBA32F test = test::with_pixel(test::scaled(reference, 1.1f), 3, 5, {4, 4, 4});
    const metrics::ReferenceErrors errors(reference, 4);
    const metrics::FrameErrors measured = errors.measure(test);
    const metrics::Metrics full = metrics::compare_images(test, reference);
    const metrics::Metrics small =
        metrics::compare_images(metrics::box_downsample(test, 4), metrics::box_downsample(reference, 4));
    // Same inputs, same code: equal to the last bit.
    EXPECT_EQ(measured.full.rel_mse, full.rel_mse);
    EXPECT_EQ(measured.full.flip_mean, full.flip_mean);
    EXPECT_EQ(measured.downsampled.rel_mse, small.rel_mse);
    EXPECT_EQ(measured.downsampled.flip_mean, small.flip_mean);
    EXPECT_EQ(measured.downsampled.bias, small.bias);
    EXPECT_GT(measured.downsampled.rel_mse, 0.0);
}

TEST(metrics_reference_errors, CausticLayerRelMseWhenBothCarryIt) {
    // The layers are 1.5 against 1 everywhere: s = 1, every term 0.25 / 1.01.
    const ImageRGBA32F reference = with_layer(gradient(), metrics::kCausticLayer, 1.0f);
    const ImageRGBA32F test = with_layer(gradient(), metrics::kCausticLayer, 1.5f);
    const metrics::FrameErrors measured = metrics::ReferenceErrors(reference, 4).measure(test);
    ASSERT_TRUE(measured.caustic.value.has_value()) << measured.caustic.missing_reason;
    test::expect_relative(*measured.caustic.value, 0.25 / 1.01);
    EXPECT_EQ(measured.full.rel_mse, 0.0);  // the main images are the same
}

TEST(metrics_reference_errors, CausticLayerIsNotAvailableWithoutBothLayers) {
    const ImageRGBA32F plain = gradient();
    const ImageRGBA32F layered = with_layer(gradient(), metrics::kCausticLayer, 1.0f);
    const metrics::LayerRelMse no_test_layer = metrics::ReferenceErrors(layered, 4).measure(plain).caustic;
    EXPECT_FALSE(no_test_layer.value.has_value());
    EXPECT_EQ(no_test_layer.text(), "n/a");
    EXPECT_EQ(no_test_layer.text(true), "n/a (the test image has no layer 'caustic')");
    const metrics::LayerRelMse no_reference_layer = metrics::ReferenceErrors(plain, 4).measure(layered).caustic;
    EXPECT_EQ(no_reference_layer.text(true), "n/a (the reference has no layer 'caustic')");
    // A black reference layer (no water in view) has no relMSE: its mean divides.
    const ImageRGBA32F black = with_layer(gradient(), metrics::kCausticLayer, 0.0f);
    const metrics::LayerRelMse black_reference = metrics::ReferenceErrors(black, 4).measure(layered).caustic;
    EXPECT_EQ(black_reference.text(true), "n/a (the reference's layer 'caustic' is black over the compared pixels)");
}

TEST(metrics_reference_errors, LayerRelMseTextHasSixDigits) {
    EXPECT_EQ((metrics::LayerRelMse{0.123456789, ""}.text()), "0.123457");
}

}  // namespace
}  // namespace vkw
