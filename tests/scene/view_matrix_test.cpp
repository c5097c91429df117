// view_matrix: right-handed look-at with up = +y, falling back to -z near vertical.
#include <cmath>

#include <gtest/gtest.h>

#include "engine/scene/scene.hpp"

namespace vkw {
namespace {

bool all_finite(const glm::dmat4& m) {
    for (int c = 0; c < 4; ++c) {
        for (int r = 0; r < 4; ++r) {
            if (!std::isfinite(m[c][r])) return false;
        }
    }
    return true;
}

// The world direction that appears at the top of the image: row 1 of the rotation.
glm::dvec3 screen_up(const glm::dmat4& view) { return {view[0][1], view[1][1], view[2][1]}; }

TEST(scene_view_matrix, StraightDownIsFiniteWithNorthUp) {
    Camera camera;
    camera.position = {0.0, 5.0, 0.0};
    camera.target = {0.0, 0.0, 0.0};
    const glm::dmat4 view = view_matrix(camera);
    ASSERT_TRUE(all_finite(view));
    const glm::dvec3 up = screen_up(view);
    EXPECT_NEAR(up.x, 0.0, 1e-12);
    EXPECT_NEAR(up.y, 0.0, 1e-12);
    EXPECT_NEAR(up.z, -1.0, 1e-12);
    // The target lies straight ahead, on the -z axis of view space.
    const glm::dvec4 target = view * glm::dvec4(camera.target, 1.0);
    EXPECT_NEAR(target.x, 0.0, 1e-12);
    EXPECT_NEAR(target.y, 0.0, 1e-12);
    EXPECT_NEAR(target.z, -5.0, 1e-12);
}

TEST(scene_view_matrix, StraightUpAndNearlyVerticalAreFinite) {
    Camera camera;
    camera.position = {1.0, -2.0, 3.0};
    camera.target = {1.0, 10.0, 3.0};
    EXPECT_TRUE(all_finite(view_matrix(camera)));
    camera.target = {1.0 + 1e-9, -10.0, 3.0};
    EXPECT_TRUE(all_finite(view_matrix(camera)));
}

TEST(scene_view_matrix, ObliqueViewKeepsYUp) {
    Camera camera;
    camera.position = {0.0, 1.2, 4.0};
    camera.target = {0.0, -1.5, -2.0};
    const glm::dmat4 view = view_matrix(camera);
    ASSERT_TRUE(all_finite(view));
    EXPECT_GT(screen_up(view).y, 0.9);
    EXPECT_NEAR(screen_up(view).x, 0.0, 1e-12);
}

}  // namespace
}  // namespace vkw
