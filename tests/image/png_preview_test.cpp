// Tests of write_png_preview: a real PNG comes out, with the tone curve applied per channel,
// row 0 on top, and non-finite pixels drawn magenta and counted.
#include <gtest/gtest.h>

#include <stb_image.h>

#include <array>
#include <cstdint>
#include <limits>
#include <memory>

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
    EXPECT_EQ(at(1, 0, 1), tonemap_to_srgb8(0.09f * exposure));  // exposure applied first
    EXPECT_EQ(at(0, 1, 0), 255);                                 // magenta
    EXPECT_EQ(at(0, 1, 1), 0);
    EXPECT_EQ(at(0, 1, 2), 255);
    EXPECT_EQ(at(1, 1, 2), tonemap_to_srgb8(0.5f * exposure));
}

TEST(image_png_preview, RejectsNonPositiveExposure) {
    ScratchDir dir;
    const ImageRGBA32F image = test::make_test_image(1, 1);
    EXPECT_THROW(write_png_preview(dir / "p.png", image, 0.0f), UserError);
    EXPECT_THROW(write_png_preview(dir / "p.png", image, std::numeric_limits<float>::quiet_NaN()), UserError);
}

}  // namespace
}  // namespace vkw
