// The final scan of every image a command writes (engine/image/image.hpp): a NaN or an infinity
// anywhere, in R, G, B, A or an extra layer, is a UserError naming the image; a finite image,
// however large its values, passes.
#include "engine/core/errors.hpp"
#include "engine/image/image.hpp"

#include <gtest/gtest.h>

#include <limits>
#include <string>

namespace vkw {
namespace {

ImageRGBA32F finite_image() {
    ImageRGBA32F image;
    image.width = 3;
    image.height = 2;
    image.rgba.assign(24, 1.0f);
    image.rgba[5] = std::numeric_limits<float>::max();  // large, but finite
    image.layers.push_back({"caustic", std::vector<float>(18, 0.5f)});
    return image;
}

TEST(finite_image, FiniteValuesPassHoweverLarge) {
    const ImageRGBA32F image = finite_image();
    EXPECT_EQ(count_nonfinite_values(image), 0u);
    EXPECT_NO_THROW(require_finite_image(image, "the test image"));
}

TEST(finite_image, ANanOrInfinityAnywhereIsRefusedNamingTheImage) {
    const float nan = std::numeric_limits<float>::quiet_NaN(), inf = std::numeric_limits<float>::infinity();
    for (int where = 0; where < 3; ++where) {
        ImageRGBA32F image = finite_image();
        if (where == 0) image.rgba[0] = nan;
        if (where == 1) image.rgba[23] = -inf;  // the last pixel's alpha
        if (where == 2) image.layers[0].rgb[17] = inf;
        EXPECT_EQ(count_nonfinite_values(image), 1u) << where;
        try {
            require_finite_image(image, "the test image");
            ADD_FAILURE() << "accepted a non-finite value at " << where;
        } catch (const UserError& error) {
            EXPECT_NE(std::string(error.what()).find("the test image"), std::string::npos) << error.what();
        }
    }
}

}  // namespace
}  // namespace vkw
