// Reflections below the horizon in real time (docs/model.md section 1, "Reflections below the
// horizon"): a ray that a wave's face reflects downward meets the water again, so no water pixel
// shows the sky's `ground`; and the ocean's infinite water covers every pixel under the horizon.
// The FFT ocean seen at grazing angles, its ground made green 1000 W m^-2 sr^-1 and the sun off
// (no glints), so that a pixel seeing the ground through a reflectance of at least 0.02 would read
// 20 or more.
#include "engine/scene/scene_loader.hpp"
#include "passes/frame/renderer.hpp"
#include "tests/support/gpu_test.hpp"
#include "tools/reference/reference_renderer.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>

namespace vkw::test {
namespace {

using BelowHorizon = GpuTest;

TEST_F(BelowHorizon, OceanWaterNeverShowsTheGround) {
    const Scene scene = load_scene(std::filesystem::path(VKWATER_SOURCE_DIR) / "scenes/ocean.json",
                                   {"sky.ground=[0,1000,0]", "sun.irradiance=[0,0,0]", "camera.fov_y_deg=10"});
    // A 10-degree view, 72 pixels high: a pixel is 2.4e-3 rad, so the ray one pixel under the horizon
    // from 4 m up meets the level 1.6 km away, four times as far as the floor's square reaches.
    ASSERT_TRUE(scene.water->infinite);
    const uint32_t width = 96, height = 72;
    Renderer renderer(context());
    const RenderResult result = renderer.render(scene, {width, height, true, fg::TimingMode::None});
    // The sky's largest green (zenith and horizon; the sun is off), doubled: water reflects the sky
    // with R <= 1 and lets out far less than the sky's radiance from below.
    const double bound = 2.0 * std::max(scene.sky.zenith.g, scene.sky.horizon.g);
    int water_pixels = 0;
    for (uint32_t y = 0; y < height; ++y) {
        for (uint32_t x = 0; x < width; ++x) {
            // The ocean's water is infinite: every pixel whose centre ray points at least one pixel
            // below the horizon (the ray through the centre of the pixel above points down too) is
            // water. A pixel there that showed no water would show the ground itself.
            const ref::Ray above = ref::camera_ray(scene.camera, width, height, x + 0.5, y - 0.5);
            if (!(above.direction.y < 0.0)) continue;
            ++water_pixels;
            const float green = result.image.rgba[(std::size_t(y) * width + x) * 4 + 1];
            EXPECT_LE(green, bound) << "pixel (" << x << ", " << y << ")";
        }
    }
    EXPECT_GT(water_pixels, int(width * height / 2));
}

}  // namespace
}  // namespace vkw::test
