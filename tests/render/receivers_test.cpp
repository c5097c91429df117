// Receiver meshes on the device: the top face of a box above the water is a Lambertian
// surface lit by the sun and the sky, L = rho (E_s cos(theta_s) + pi L_sky) / pi (the
// model's closed form, docs/model.md section 1), read at the pixel that sees its centre.
#include "engine/scene/scene_loader.hpp"
#include "passes/frame/renderer.hpp"
#include "tests/support/gpu_test.hpp"

#include <numbers>

namespace vkw::test {
namespace {

using ReceiverPass = GpuTest;

TEST_F(ReceiverPass, BoxTopAboveTheWaterMatchesTheClosedForm) {
    // Looking straight down at a 2 m box whose top (y = 1) fills the centre of the view.
    const Scene scene = parse_scene(R"({
      "camera": {"position": [0, 5, 0], "direction": [0, -1, 0], "fov_y_deg": 30},
      "sun": {"elevation_deg": 50, "azimuth_deg": 20, "irradiance": [2, 3, 4]},
      "sky": {"radiance": [0.2, 0.3, 0.4]},
      "floor": {"height": -2, "half_extent": 10},
      "water": {"level": 0, "half_extent": 10},
      "receivers": [{"type": "box", "half_size": [1, 1, 1], "albedo": [0.7, 0.5, 0.3]}]
    })",
                                    "box.json");
    Renderer renderer(context());
    const RenderResult result = renderer.render(scene, {33, 33, true, fg::TimingMode::None});
    const float* centre = result.image.pixel(16, 16);
    const double cos_sun = -scene.sun.direction.y;
    for (int c = 0; c < 3; ++c) {
        const double albedo = scene.receivers[0].albedo[c];
        const double expected =
            albedo * (scene.sun.irradiance[c] * cos_sun + std::numbers::pi * scene.sky.radiance[c]) / std::numbers::pi;
        // As in the first-pixels test: ~10 fp32 roundings of the inputs and the shading,
        // plus the interpolated normal's renormalisation (another few): 2e-6 relative.
        EXPECT_NEAR(centre[c], expected, 2e-6 * expected) << "channel " << c;
    }
}

}  // namespace
}  // namespace vkw::test
