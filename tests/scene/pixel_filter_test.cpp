// engine/scene/pixel_filter.hpp: the samples of a box-filtered pixel and the image-plane shift
// that makes a pixel's centre show a chosen sub-pixel point.
#include "engine/scene/pixel_filter.hpp"
#include "engine/core/errors.hpp"
#include "engine/scene/scene.hpp"

#include <gtest/gtest.h>

#include <set>
#include <utility>

namespace vkw {
namespace {

TEST(scene_pixel_filter, SquaresFromOneTo256AreAcceptedAndNothingElse) {
    EXPECT_FALSE(pixel_filter_from_spp(1).is_box());
    EXPECT_EQ(pixel_filter_from_spp(16).side(), 4u);
    EXPECT_EQ(pixel_filter_from_spp(256).side(), 16u);
    for (const int64_t bad : {0, -4, 2, 3, 8, 15, 17, 289}) {
        try {
            pixel_filter_from_spp(bad);
            ADD_FAILURE() << bad << " was accepted";
        } catch (const UserError& e) {
            EXPECT_NE(std::string(e.what()).find("--spp " + std::to_string(bad)), std::string::npos) << e.what();
            EXPECT_NE(std::string(e.what()).find("accepted: 1, 4, 9, 16"), std::string::npos) << e.what();
        }
    }
    EXPECT_EQ(pixel_filter_from_spp(1).describe(), "point: one sample at each pixel centre");
    EXPECT_EQ(pixel_filter_from_spp(16).describe(), "box: 16 samples per pixel (4 x 4 strata)");
    EXPECT_EQ(pixel_filter_kind(pixel_filter_from_spp(9).describe()), "box");
    EXPECT_EQ(pixel_filter_kind(pixel_filter_from_spp(1).describe()), "point");
    EXPECT_EQ(pixel_filter_kind("gaussian"), "");
}

// Each sample lies in its own stratum of the pixel (k x k squares of side 1/k about the centre),
// the centres' mean is the pixel's centre, and the reference's jitter is a function of the pixel
// and the sample alone: the same every call, different between neighbouring pixels.
TEST(scene_pixel_filter, SamplesFillTheirStrata) {
    for (const uint32_t spp : {4u, 9u, 16u}) {
        const PixelFilter filter = pixel_filter_from_spp(spp);
        const double k = filter.side();
        glm::dvec2 mean(0.0);
        for (uint32_t i = 0; i < spp; ++i) {
            const glm::dvec2 stratum((i % filter.side()) / k - 0.5, (i / filter.side()) / k - 0.5);
            const glm::dvec2 centre = filter.stratum_centre(i);
            mean += centre / double(spp);
            EXPECT_NEAR(centre.x, stratum.x + 0.5 / k, 1e-15);
            EXPECT_NEAR(centre.y, stratum.y + 0.5 / k, 1e-15);
            for (uint32_t x = 0; x < 8; ++x) {
                const glm::dvec2 jittered = filter.jittered_sample(x, 3, i);
                EXPECT_GE(jittered.x, stratum.x);
                EXPECT_LT(jittered.x, stratum.x + 1.0 / k);
                EXPECT_GE(jittered.y, stratum.y);
                EXPECT_LT(jittered.y, stratum.y + 1.0 / k);
                EXPECT_EQ(jittered, filter.jittered_sample(x, 3, i));
            }
            EXPECT_NE(filter.jittered_sample(0, 3, i), filter.jittered_sample(1, 3, i));
        }
        EXPECT_NEAR(mean.x, 0.0, 1e-15);
        EXPECT_NEAR(mean.y, 0.0, 1e-15);
    }
}

// The shifted projection puts the world point that an unshifted camera sees at pixel coordinate
// (x + 0.5 + o) on the centre of pixel x (NDC x = 2 X / W - 1, y = 1 - 2 Y / H, as camera_ray).
TEST(scene_pixel_filter, TheShiftBringsTheOffsetPointToThePixelCentre) {
    Camera camera;
    camera.position = {1.0, 2.0, 3.0};
    camera.target = {0.0, 0.0, -4.0};
    constexpr uint32_t kW = 40, kH = 30;
    const glm::dvec2 offset(0.3, -0.2);
    const glm::dvec2 pixel(12.0, 7.0);
    const double aspect = double(kW) / kH;
    const glm::dmat4 plain = projection_matrix(camera, aspect) * view_matrix(camera);
    const glm::dvec2 at = pixel + 0.5 + offset;
    const glm::dvec4 point = glm::inverse(plain) * glm::dvec4(2.0 * at.x / kW - 1.0, 1.0 - 2.0 * at.y / kH, 0.5, 1.0);
    Camera shifted = camera;
    shifted.image_shift_ndc = image_shift_for_pixel_offset(offset, kW, kH);
    const glm::dvec4 clip = projection_matrix(shifted, aspect) * view_matrix(shifted) * (point / point.w);
    EXPECT_NEAR(clip.x / clip.w, 2.0 * (pixel.x + 0.5) / kW - 1.0, 1e-12);
    EXPECT_NEAR(clip.y / clip.w, 1.0 - 2.0 * (pixel.y + 0.5) / kH, 1e-12);
}

}  // namespace
}  // namespace vkw
