// Tests of write_png_preview: a real PNG comes out, with the tone curve applied per channel,
// row 0 on top, non-finite pixels drawn magenta and counted, dithered without bands and with an
// sRGB chunk.
#include <gtest/gtest.h>

#include <stb_image.h>

#include <zlib.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <memory>
#include <vector>

#include "engine/image/png_preview.hpp"
#include "engine/image/tone_curve.hpp"
#include "tests/image/image_test_support.hpp"

namespace vkw {
namespace {

using test::ScratchDir;

TEST(image_png_preview, WritesPngWithToneMappedPixels) {
    ScratchDir dir;
    ImageRGBA32F image;
    image.width = 2;
    image.height = 2;
    image.rgba = {
        0.0f,
        0.0f,
        0.0f,
        1.0f,  // (0,0) top left: black
        1.0e6f,
        0.09f,
        0.0f,
        0.0f,  // (1,0) top right
        std::numeric_limits<float>::quiet_NaN(),
        0.0f,
        0.0f,
        1.0f,  // (0,1) bottom left
        0.5f,
        0.5f,
        0.5f,
        1.0f,  // (1,1) bottom right
    };
    const float exposure = 2.0f;

    const std::size_t nonfinite = write_png_preview(dir / "preview.png", image, exposure);
    EXPECT_EQ(nonfinite, 1u);

    const auto bytes = test::read_bytes(dir / "preview.png");
    const std::array<unsigned char, 8> signature = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1A, '\n'};
    ASSERT_GE(bytes.size(), signature.size());
    EXPECT_TRUE(std::equal(signature.begin(), signature.end(), bytes.begin()));

    int width = 0, height = 0, channels = 0;
    std::unique_ptr<stbi_uc, void (*)(void*)> pixels(
        stbi_load((dir / "preview.png").c_str(), &width, &height, &channels, 3), stbi_image_free);
    ASSERT_NE(pixels, nullptr);
    EXPECT_EQ(width, 2);
    EXPECT_EQ(height, 2);
    EXPECT_EQ(channels, 3);  // alpha is not written
    auto at = [&](int x, int y, int c) { return pixels.get()[(y * 2 + x) * 3 + c]; };

    EXPECT_EQ(at(0, 0, 0), 0);
    EXPECT_EQ(at(1, 0, 0), 255);
    // Exposure applied first; the dither moves a value by one level at most.
    EXPECT_LE(std::abs(at(1, 0, 1) - tonemap_to_srgb8(0.09f * exposure)), 1);
    EXPECT_EQ(at(0, 1, 0), 255);  // magenta
    EXPECT_EQ(at(0, 1, 1), 0);
    EXPECT_EQ(at(0, 1, 2), 255);
    EXPECT_LE(std::abs(at(1, 1, 2) - tonemap_to_srgb8(0.5f * exposure)), 1);
    // The same image gives the same bytes: the dither is keyed by the pixel, not drawn at random.
    write_png_preview(dir / "again.png", image, exposure);
    EXPECT_EQ(test::read_bytes(dir / "again.png"), bytes);
}

// The sRGB chunk right after IHDR (PNG 1.2, 11.3.3.5): length 1, rendering intent 0, its CRC.
TEST(image_png_preview, CarriesAnSrgbChunkAfterIhdr) {
    ScratchDir dir;
    write_png_preview(dir / "p.png", test::make_test_image(3, 2), 1.0f);
    const auto bytes = test::read_bytes(dir / "p.png");
    ASSERT_GE(bytes.size(), 46u);
    const std::vector<unsigned char> chunk(bytes.begin() + 33, bytes.begin() + 46);
    const unsigned char type_and_data[] = {'s', 'R', 'G', 'B', 0};
    const uLong crc = crc32(crc32(0L, Z_NULL, 0), type_and_data, 5);
    const std::vector<unsigned char> expected = {0,
                                                 0,
                                                 0,
                                                 1,
                                                 's',
                                                 'R',
                                                 'G',
                                                 'B',
                                                 0,
                                                 static_cast<unsigned char>(crc >> 24),
                                                 static_cast<unsigned char>(crc >> 16),
                                                 static_cast<unsigned char>(crc >> 8),
                                                 static_cast<unsigned char>(crc)};
    EXPECT_EQ(chunk, expected);
    int width = 0, height = 0, channels = 0;  // and a decoder still reads the file
    std::unique_ptr<stbi_uc, void (*)(void*)> pixels(stbi_load((dir / "p.png").c_str(), &width, &height, &channels, 3),
                                                     stbi_image_free);
    EXPECT_NE(pixels, nullptr);
    EXPECT_EQ(width, 3);
}

// Every encoded value, at many pixels and in every channel, lands within one level of the
// undithered rounding; black and white (where the tone curve clamps) stay exact.
TEST(image_png_preview, TheDitherMovesAValueByOneLevelAtMost) {
    int moved = 0;
    for (int step = 0; step <= 2550; ++step) {
        const float encoded = static_cast<float>(step) / 2550.0f;
        for (std::uint32_t pixel = 0; pixel < 64; ++pixel) {
            for (std::uint32_t c = 0; c < 3; ++c) {
                const int dithered = to_unorm8_dithered(encoded, pixel * 7, pixel * 13, c);
                const int plain = to_unorm8(encoded);
                ASSERT_LE(std::abs(dithered - plain), 1) << encoded << " at " << pixel;
                moved += dithered != plain;
            }
        }
    }
    EXPECT_GT(moved, 0);  // it does dither
    for (std::uint32_t x = 0; x < 1000; ++x) {
        EXPECT_EQ(to_unorm8_dithered(0.0f, x, 3, 1), 0);
        EXPECT_EQ(to_unorm8_dithered(1.0f, x, 3, 1), 255);
    }
}

// A smooth ramp over about five 8-bit levels, 1000 columns by 256 rows. Undithered it is five
// bands about 200 columns wide, each column off its true value by up to half a level. Dithered:
// - each column's mean over its 256 rows is the ramp's value: a triangular dither 2 levels wide
//   makes the rounding error's mean 0 and its variance 1/4 level^2, so the mean of 256
//   independent pixels has a standard deviation of 1/32 level; bound 0.19 (6 of them);
// - no run of equal values along a row is 93 pixels long: a pixel takes any one level with a
//   probability of at most 3/4 (where the value sits on that level and |dither| < 1/2), so a run of
//   L starting at a given pixel has a probability of at most (3/4)^(L-1), and over the 256,000
//   starts some run of 93 or more has one below 1e-6.
TEST(image_png_preview, ARampHasNoBandsAndKeepsItsValueOnAverage) {
    constexpr int kWidth = 1000, kHeight = 256, kLongestRun = 92;
    constexpr double kMeanBound = 0.19;
    const auto ramp = [](int x) { return 0.40f + 0.02f * static_cast<float>(x) / static_cast<float>(kWidth - 1); };
    double worst_mean_dithered = 0.0, worst_mean_plain = 0.0;
    for (int x = 0; x < kWidth; ++x) {
        double dithered = 0.0;
        for (int y = 0; y < kHeight; ++y) dithered += to_unorm8_dithered(ramp(x), x, y, 0);
        const double truth = ramp(x) * 255.0;
        worst_mean_dithered = std::max(worst_mean_dithered, std::abs(dithered / kHeight - truth));
        worst_mean_plain = std::max(worst_mean_plain, std::abs(double(to_unorm8(ramp(x))) - truth));
    }
    EXPECT_LT(worst_mean_dithered, kMeanBound);
    EXPECT_GT(worst_mean_plain, 0.45);  // the undithered ramp fails the same bound
    const auto longest_run = [&](bool dither) {
        int longest = 0;
        for (int y = 0; y < kHeight; ++y) {
            int run = 1;
            for (int x = 1; x < kWidth; ++x) {
                const auto value = [&](int at) {
                    return dither ? to_unorm8_dithered(ramp(at), at, y, 0) : to_unorm8(ramp(at));
                };
                run = value(x) == value(x - 1) ? run + 1 : 1;
                longest = std::max(longest, run);
            }
        }
        return longest;
    };
    EXPECT_LE(longest_run(true), kLongestRun);
    EXPECT_GT(longest_run(false), kLongestRun);  // bands the dither breaks up
}

TEST(image_png_preview, RejectsNonPositiveExposure) {
    ScratchDir dir;
    const ImageRGBA32F image = test::make_test_image(1, 1);
    EXPECT_THROW(write_png_preview(dir / "p.png", image, 0.0f), UserError);
    EXPECT_THROW(write_png_preview(dir / "p.png", image, std::numeric_limits<float>::quiet_NaN()), UserError);
}

}  // namespace
}  // namespace vkw
