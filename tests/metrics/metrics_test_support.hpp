// Test images for the metrics tests, and the tolerance the hand-computed answers are held to.
#pragma once

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstddef>
#include <functional>
#include <string>
#include <vector>

#include "engine/core/errors.hpp"
#include "engine/image/image.hpp"
#include "tools/metrics/rgb_view.hpp"

namespace vkw::test {

// The metrics compute in double with compensated sums; the answers below are computed by hand
// (in double) from the definitions. Both round only a few operations per term, so they agree to
// well within 1e-12 relative; anything larger is a different formula, not rounding.
inline constexpr double kRelativeTolerance = 1e-12;

inline void expect_relative(double actual, double expected) {
    EXPECT_NEAR(actual, expected, kRelativeTolerance * std::abs(expected)) << "expected " << expected;
}

using Rgb = std::array<float, 3>;

// A width x height image whose pixel (x, y) has RGB colour(x, y) and alpha 1.
inline ImageRGBA32F make_image(int width, int height, const std::function<Rgb(int, int)>& colour) {
    ImageRGBA32F image;
    image.width = width;
    image.height = height;
    image.rgba.resize(image.pixel_count() * 4);
    for (int y = 0; y < height; ++y) {
        for (int x = 0; x < width; ++x) {
            const Rgb c = colour(x, y);
            float* p = image.pixel(x, y);
            p[0] = c[0];
            p[1] = c[1];
            p[2] = c[2];
            p[3] = 1.0f;
        }
    }
    return image;
}

inline ImageRGBA32F constant_image(int width, int height, Rgb colour) {
    return make_image(width, height, [colour](int, int) { return colour; });
}

inline ImageRGBA32F grey_image(int width, int height, float grey) {
    return constant_image(width, height, {grey, grey, grey});
}

// Every value multiplied by k (alpha kept).
inline ImageRGBA32F scaled(ImageRGBA32F image, float k) {
    for (std::size_t i = 0; i < image.rgba.size(); ++i) {
        if (i % 4 != 3) image.rgba[i] *= k;
    }
    return image;
}

// Every RGB value plus d.
inline ImageRGBA32F offset(ImageRGBA32F image, float d) {
    for (std::size_t i = 0; i < image.rgba.size(); ++i) {
        if (i % 4 != 3) image.rgba[i] += d;
    }
    return image;
}

// The image with pixel (x, y) set to colour.
inline ImageRGBA32F with_pixel(ImageRGBA32F image, int x, int y, Rgb colour) {
    float* p = image.pixel(x, y);
    p[0] = colour[0];
    p[1] = colour[1];
    p[2] = colour[2];
    return image;
}

// The message of the UserError `call` throws (a test failure if it throws none).
inline std::string user_error_message(const std::function<void()>& call) {
    try {
        call();
    } catch (const UserError& error) {
        return error.what();
    }
    ADD_FAILURE() << "no UserError";
    return {};
}

// Every pixel of the image counts.
inline std::vector<std::size_t> all_pixels(const ImageRGBA32F& image) {
    return metrics::counted_pixels(image.width, image.height, nullptr);
}

}  // namespace vkw::test
