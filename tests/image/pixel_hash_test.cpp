// The pixel hash a sequence's manifest records: over the pixel data alone, bit for bit.
#include "engine/image/pixel_hash.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace vkw {
namespace {

ImageRGBA32F two_pixels() {
    ImageRGBA32F image;
    image.width = 2;
    image.height = 1;
    image.rgba = {0.25f, 0.5f, 0.75f, 1.0f, 1.0f, 2.0f, 3.0f, 1.0f};
    image.layers = {{"caustic", {0.1f, 0.2f, 0.3f, 0.4f, 0.5f, 0.6f}}, {"inscatter", {0, 0, 0, 1, 1, 1}}};
    return image;
}

TEST(image_PixelHash, SixteenHexDigitsThatIgnoreAttributesAndLayerOrder) {
    const ImageRGBA32F image = two_pixels();
    const std::string hash = pixel_hash(image);
    EXPECT_EQ(hash.size(), 16u);
    EXPECT_EQ(hash.find_first_not_of("0123456789abcdef"), std::string::npos);
    ImageRGBA32F other = image;
    other.attributes = {{"vkwater/time", "12 ms"}};
    std::swap(other.layers[0], other.layers[1]);  // read_exr sorts them by name; a render need not
    EXPECT_EQ(pixel_hash(other), hash);
}

// Any one bit of any value, a layer's name, or the shape changes it.
TEST(image_PixelHash, ChangesWithEveryBit) {
    const ImageRGBA32F image = two_pixels();
    const std::string hash = pixel_hash(image);
    for (size_t i = 0; i < image.rgba.size(); ++i) {
        ImageRGBA32F changed = image;
        changed.rgba[i] = std::nextafter(changed.rgba[i], 10.0f);
        EXPECT_NE(pixel_hash(changed), hash) << i;
    }
    ImageRGBA32F signed_zero = image;
    signed_zero.layers[1].rgb[0] = -0.0f;  // equal as a number, not as stored
    EXPECT_NE(pixel_hash(signed_zero), hash);
    ImageRGBA32F renamed = image;
    renamed.layers[0].name = "caustics";
    EXPECT_NE(pixel_hash(renamed), hash);
    ImageRGBA32F transposed = image;
    transposed.width = 1;
    transposed.height = 2;
    EXPECT_NE(pixel_hash(transposed), hash);
}

}  // namespace
}  // namespace vkw
