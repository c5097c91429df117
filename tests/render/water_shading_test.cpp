// The water shading core on the device against closed forms (the shading issue's tests):
// flat water seen from above at camera elevations 5, 20, 45 and 90 degrees (docs/model.md
// section 3, through the reference renderer, which its own tests hold to the closed
// form within 1e-8); Snell's window's radius measured on the real-time image (section
// 7); and finite output while the view sweeps through the horizon and with the camera on
// the water plane.
#include "engine/scene/scene_loader.hpp"
#include "passes/frame/renderer.hpp"
#include "tests/support/gpu_test.hpp"
#include "tools/reference/reference_renderer.hpp"

#include <cmath>
#include <filesystem>
#include <numbers>
#include <string>

namespace vkw::test {
namespace {

constexpr double kPi = std::numbers::pi;

Scene calm(const std::vector<std::string>& overrides) {
    return load_scene(std::filesystem::path(VKWATER_SOURCE_DIR) / "scenes/calm.json", overrides);
}

using WaterShading = GpuTest;

TEST_F(WaterShading, FlatWaterFromAboveMatchesTheClosedFormAtFourElevations) {
    Renderer renderer(context());
    for (double elevation : {5.0, 20.0, 45.0, 90.0}) {
        SCOPED_TRACE("camera elevation " + std::to_string(elevation));
        // A narrow view straight down the given elevation, 3 m above the water.
        const double e = elevation * kPi / 180.0;
        const std::string direction =
            elevation == 90.0 ? "[0, -1, 0]"
                              : "[0, " + std::to_string(-std::sin(e)) + ", " + std::to_string(-std::cos(e)) + "]";
        const Scene scene = calm({"camera.direction=" + direction, "camera.fov_y_deg=2"});
        const RenderResult image = renderer.render(scene, {9, 9, true, fg::TimingMode::None});
        const ImageRGBA32F reference = ref::render_reference(scene, {9, 9, 1, {}});
        for (int c = 0; c < 3; ++c) {
            const double expected = reference.pixel(4, 4)[c];
            // fp32 shading chain (see water_vs_reference_test.cpp): 1e-5 relative.
            EXPECT_NEAR(image.image.pixel(4, 4)[c], expected, 1e-5 * expected) << "channel " << c;
        }
    }
}

TEST_F(WaterShading, SnellsWindowRadiusOnTheRealTimeImage) {
    // docs/model.md section 7: albedo 0, constant sky, sigma_s = 0, E_s = 0 (scenes/underwater.json),
    // looking straight up with a 120 degree field of view.
    const Scene scene = load_scene(std::filesystem::path(VKWATER_SOURCE_DIR) / "scenes/underwater.json");
    const uint32_t size = 301;
    Renderer renderer(context());
    const RenderResult result = renderer.render(scene, {size, size, true, fg::TimingMode::None});
    const int centre = size / 2;
    const double centre_value = result.image.pixel(centre, centre)[2];
    ASSERT_GT(centre_value, 0.0);
    int radius = -1;
    for (int x = centre; x < int(size); ++x) {
        if (result.image.pixel(x, centre)[2] < 1e-3 * centre_value) {
            radius = x - centre;
            break;
        }
    }
    const double focal_px = (size / 2.0) / std::tan(scene.camera.fov_y_deg / 2.0 * kPi / 180.0);
    EXPECT_NEAR(radius, focal_px * std::tan(std::asin(1.0 / scene.water->ior)), 1.0);  // within one pixel
}

TEST_F(WaterShading, FiniteThroughTheHorizonAndOnTheWaterPlane) {
    // The finite check (on) names any pass that writes NaN/Inf; validation runs too.
    Renderer renderer(context());
    for (double pitch = -30.0; pitch <= 30.0; pitch += 7.5) {
        const double p = pitch * kPi / 180.0;
        for (double height : {1.0, 1e-6, 0.0, -1e-6, -1.0}) {
            const Scene scene =
                calm({"camera.position=[0, " + std::to_string(height) + ", 0]",
                      "camera.direction=[0, " + std::to_string(std::sin(p)) + ", " + std::to_string(-std::cos(p)) + "]",
                      "camera.fov_y_deg=90"});
            EXPECT_NO_THROW(renderer.render(scene, {24, 16, true, fg::TimingMode::None}))
                << "pitch " << pitch << ", height " << height;
        }
    }
}

}  // namespace
}  // namespace vkw::test
