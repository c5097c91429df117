// The sky seen directly on the device: the gradient model of scenes/README.md,
// L = mix(horizon, zenith, dir.y^e) above the horizon, checked at every pixel whose
// ray rises against vkw::sky_radiance evaluated on that pixel's ray in double.
#include "engine/scene/scene_loader.hpp"
#include "passes/frame/renderer.hpp"
#include "tests/support/gpu_test.hpp"
#include "tools/reference/reference_renderer.hpp"

#include <cmath>

namespace vkw::test {
namespace {

using SkyPass = GpuTest;

TEST_F(SkyPass, GradientSkyMatchesTheCpuFormulaAtEveryRisingPixel) {
    const Scene scene = parse_scene(R"({
      "camera": {"position": [0, 1, 0], "direction": [0, 0.3, -1], "fov_y_deg": 90},
      "sun": {"elevation_deg": -10, "irradiance": [1, 1, 1]},
      "sky": {"model": "gradient", "zenith": [0.1, 0.3, 0.9], "horizon": [0.8, 0.7, 0.6],
              "ground": [0.2, 0.2, 0.2], "exponent": 0.5},
      "floor": {"height": -100, "half_extent": 1}
    })",
                                    "gradient_sky.json");
    const uint32_t width = 64, height = 48;
    Renderer renderer(context());
    const RenderResult result = renderer.render(scene, {width, height, true, fg::TimingMode::None});
    int checked = 0;
    for (uint32_t y = 0; y < height; ++y) {
        for (uint32_t x = 0; x < width; ++x) {
            const glm::dvec3 dir = ref::camera_ray(scene.camera, width, height, x + 0.5, y + 0.5).direction;
            if (dir.y < 0.02) continue;  // the ground, and the kink at the horizon
            const glm::dvec3 expected = sky_radiance(scene.sky, dir);
            // The shader rebuilds the ray from the inverse view-projection in fp32: its
            // direction is off by ~1e-6 (a few roundings of 2^-24 on O(1) values), which
            // moves L by |z - h| e y^(e-1) times that; pow() and mix() add ~8 roundings.
            const double slope = scene.sky.exponent * std::pow(dir.y, scene.sky.exponent - 1.0);
            for (int c = 0; c < 3; ++c) {
                const double tolerance = std::abs(scene.sky.zenith[c] - scene.sky.horizon[c]) * slope * 2e-6 +
                                         8 * std::ldexp(expected[c], -24);
                EXPECT_NEAR(result.image.pixel(int(x), int(y))[c], expected[c], tolerance)
                    << x << "," << y << " channel " << c;
            }
            ++checked;
        }
    }
    EXPECT_GT(checked, int(width * height / 3));
}

}  // namespace
}  // namespace vkw::test
