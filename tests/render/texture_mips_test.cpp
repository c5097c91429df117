// The real-time base colour texels (passes/receivers/texture_mips.hpp), on the CPU: half floats
// within half an ulp, the exact sRGB decoding, and mip levels that average in linear colour.
#include "passes/receivers/texture_mips.hpp"

#include <cmath>

#include <gtest/gtest.h>
#include <glm/gtc/packing.hpp>

namespace vkw::passes {
namespace {

// The uploaded texels' precision, which the textured receiver tests rely on: every value in
// [1e-4, 1] within half a half-float ulp, 2^-11 relative.
TEST(TextureMips, HalfFloatsStayWithinHalfAnUlp) {
    for (float v = 1e-4f; v <= 1.0f; v *= 1.01f) {
        const float back = glm::unpackHalf1x16(glm::packHalf1x16(v));
        EXPECT_LE(std::abs(back - v), std::ldexp(v, -11)) << v;
    }
}

TEST(TextureMips, LevelsAverageTheDecodedColour) {
    // A 2 x 2 checker of black and sRGB 255 white: one level below, the linear mean 0.5 (its sRGB
    // encoding would be 188, not the 128 an average of the bytes would give).
    TextureImage checker{2, 2, {0, 0, 0, 255, 255, 255, 255, 255, 255, 255, 255, 255, 0, 0, 0, 255}};
    const std::vector<MipLevel> levels = linear_mip_chain(checker);
    ASSERT_EQ(levels.size(), 2u);
    EXPECT_EQ(levels[0].width, 2u);
    EXPECT_EQ(glm::unpackHalf1x16(levels[0].rgba[4]), 1.0f);
    ASSERT_EQ(levels[1].width, 1u);
    for (int c = 0; c < 3; ++c) EXPECT_EQ(glm::unpackHalf1x16(levels[1].rgba[std::size_t(c)]), 0.5f);
    EXPECT_EQ(glm::unpackHalf1x16(levels[1].rgba[3]), 1.0f);  // alpha
    // sRGB 128 decodes to 0.2158605 (IEC 61966-2-1); as a half, within 2^-11 of it.
    TextureImage grey{1, 1, {128, 128, 128, 255}};
    EXPECT_NEAR(glm::unpackHalf1x16(linear_mip_chain(grey)[0].rgba[0]), 0.2158605, 0.2158605 * std::ldexp(1.0, -11));
    // A 5 x 3 image: levels 2 x 1 and 1 x 1.
    TextureImage odd{5, 3, std::vector<uint8_t>(60, 255)};
    const std::vector<MipLevel> odd_levels = linear_mip_chain(odd);
    ASSERT_EQ(odd_levels.size(), 3u);
    EXPECT_EQ(odd_levels[1].width, 2u);
    EXPECT_EQ(odd_levels[1].height, 1u);
    EXPECT_EQ(odd_levels[2].width * odd_levels[2].height, 1u);
    EXPECT_EQ(glm::unpackHalf1x16(odd_levels[2].rgba[0]), 1.0f);  // white stays white
}

}  // namespace
}  // namespace vkw::passes
