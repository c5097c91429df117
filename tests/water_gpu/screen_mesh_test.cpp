// The screen grid's margin and cell counts (passes/water/water_screen_mesh.hpp) against their
// closed forms. CPU only.
#include "passes/water/water_screen_mesh.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

namespace vkw::test {
namespace {

Camera camera_at(double height) {
    Camera camera;
    camera.position = {0.0, height, 4.0};
    camera.target = {0.0, height - 2.7, -2.0};
    camera.fov_y_deg = 60.0;
    return camera;
}

TEST(water_gpu_screen_mesh, FlatWaterNeedsNoMargin) {
    EXPECT_EQ(passes::screen_mesh(8, camera_at(1.2), 4.0 / 3.0, 0.0, 0.0).margin, 0.0f);
}

TEST(water_gpu_screen_mesh, MarginIsTheDisplacementsReachOnTheScreen) {
    // pool's camera (1.2 m over the level) and amplitude bound (2 x 0.017 m), 4:3.
    const double amplitude = 0.034, aspect = 4.0 / 3.0;
    const double tan_y = std::tan(std::numbers::pi / 6.0), tan_x = tan_y * aspect;
    const double widest = 1.0 + passes::kMaxScreenMeshMargin;
    const double cos_corner = 1.0 / std::sqrt(1.0 + (tan_x * tan_x + tan_y * tan_y) * widest * widest);
    const double displacement = std::sqrt(2.0) * amplitude;
    const double depth = (1.2 - amplitude) * cos_corner;
    const double expected = (1.0 / tan_y + widest) * displacement / (depth - displacement);
    const passes::ScreenMesh mesh = passes::screen_mesh(8, camera_at(1.2), aspect, 0.0, amplitude);
    // The same arithmetic in double, rounded once to float: within one float ulp.
    EXPECT_NEAR(mesh.margin, expected, 1e-7 * expected);
    EXPECT_GT(mesh.margin, 0.1f);  // about 0.27: the bound is not vacuous
    EXPECT_LT(mesh.margin, 0.5f);
    EXPECT_EQ(mesh.amplitude, static_cast<float>(amplitude));
}

TEST(water_gpu_screen_mesh, ACameraInsideTheSlabGetsTheLargestMargin) {
    // 0.02 m over the level with waves of 0.05 m: a crest can come as near as the near plane.
    EXPECT_EQ(passes::screen_mesh(8, camera_at(0.02), 1.0, 0.0, 0.05).margin,
              static_cast<float>(passes::kMaxScreenMeshMargin));
    // Far above, the margin shrinks as 1 / height.
    const float high = passes::screen_mesh(8, camera_at(100.0), 1.0, 0.0, 0.05).margin;
    const float higher = passes::screen_mesh(8, camera_at(200.0), 1.0, 0.0, 0.05).margin;
    EXPECT_NEAR(high / higher, 2.0, 0.01);
}

TEST(water_gpu_screen_mesh, CellsCoverTheWidenedViewport) {
    passes::ScreenMesh mesh;
    mesh.cell_pixels = 8;
    mesh.margin = 0.25f;
    // 800 x 1.25 / 8 = 125, 600 x 1.25 / 8 = 93.75 -> 94.
    EXPECT_EQ(passes::screen_mesh_cells(mesh, {800, 600}), glm::uvec2(125, 94));
    mesh.cell_pixels = 64;
    EXPECT_EQ(passes::screen_mesh_cells(mesh, {10, 10}), glm::uvec2(1, 1));
}

}  // namespace
}  // namespace vkw::test
