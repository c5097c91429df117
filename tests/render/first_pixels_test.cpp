// First pixels: the default scene without its water (a constant sky over a sunlit
// Lambertian floor) rendered on the device, written to OpenEXR, read back with OpenEXR,
// and checked against the model (docs/model.md section 1):
//   floor radiance = rho (E_s cos(theta_s) + pi L_sky) / pi,   sky radiance = L_sky.
#include "engine/image/exr_io.hpp"
#include "engine/scene/scene_loader.hpp"
#include "passes/common/frame_constants.hpp"
#include "passes/frame/renderer.hpp"
#include "tests/support/gpu_test.hpp"

#include <glm/glm.hpp>

#include <cmath>
#include <filesystem>
#include <numbers>

namespace vkw::test {
namespace {

constexpr uint32_t kWidth = 160;
constexpr uint32_t kHeight = 120;

// Where the camera ray through pixel (x, y)'s centre meets the floor plane, if it does
// within the floor's extent: computed in double precision from the same matrices.
bool ray_hits_floor(const Scene& scene, int x, int y) {
    const glm::dmat4 view_proj = projection_matrix(scene.camera, double(kWidth) / kHeight) * view_matrix(scene.camera);
    const glm::dmat4 inverse = glm::inverse(view_proj);
    const glm::dvec2 ndc{2.0 * (x + 0.5) / kWidth - 1.0, 1.0 - 2.0 * (y + 0.5) / kHeight};
    const glm::dvec4 near_point = inverse * glm::dvec4(ndc, 1.0, 1.0);
    const glm::dvec3 direction = glm::normalize(glm::dvec3(near_point) / near_point.w - scene.camera.position);
    if (direction.y >= 0.0) return false;
    const double t = (scene.floor.height - scene.camera.position.y) / direction.y;
    const glm::dvec3 hit = scene.camera.position + t * direction;
    return std::abs(hit.x) < scene.floor.half_extent && std::abs(hit.z) < scene.floor.half_extent;
}

using FirstPixels = GpuTest;

TEST_F(FirstPixels, DefaultSceneFloorAndSkyMatchTheModel) {
    // water=null removes the water: this test pins the foundation's sky and floor.
    const Scene scene = load_scene(std::filesystem::path(VKWATER_SOURCE_DIR) / "scenes/pool.json", {"water=null"});
    const std::filesystem::path exr = std::filesystem::path(::testing::TempDir()) / "first_pixels.exr";
    {
        Renderer renderer(context());
        const RenderResult result =
            renderer.render(scene, {kWidth, kHeight, /*check_finite=*/true, fg::TimingMode::None});
        write_exr(exr, result.image);
    }
    const ImageRGBA32F image = read_exr(exr);
    ASSERT_EQ(image.width, int(kWidth));
    ASSERT_EQ(image.height, int(kHeight));

    const int floor_x = kWidth / 2, floor_y = kHeight - 1;  // bottom centre
    const int sky_x = kWidth / 2, sky_y = 0;                // top centre
    ASSERT_TRUE(ray_hits_floor(scene, floor_x, floor_y));
    ASSERT_FALSE(ray_hits_floor(scene, sky_x, sky_y));

    const double cos_sun = -scene.sun.direction.y;
    // Tolerance: the shader evaluates about 6 fp32 operations (multiply, add, divide)
    // on inputs each rounded once from double (E_s, L_sky, rho, s): at most ~10 roundings
    // of 2^-24 relative, about 6e-7. The EXR is 32-bit float, so writing adds nothing.
    constexpr double kRelativeTolerance = 1e-6;
    for (int c = 0; c < 3; ++c) {
        const double floor_expected = scene.floor.albedo[c] *
                                      (scene.sun.irradiance[c] * cos_sun + std::numbers::pi * scene.sky.radiance[c]) /
                                      std::numbers::pi;
        EXPECT_NEAR(image.pixel(floor_x, floor_y)[c], floor_expected, kRelativeTolerance * floor_expected)
            << "floor channel " << c;
        const double sky_expected = scene.sky.radiance[c];
        EXPECT_NEAR(image.pixel(sky_x, sky_y)[c], sky_expected, kRelativeTolerance * sky_expected)
            << "sky channel " << c;
    }
}

TEST_F(FirstPixels, SunDiskShowsWithTheModelsRadiance) {
    // Look straight at the sun: the centre pixel sees the disk, radiance L_sky + E_s / 6.80e-5.
    Scene scene = load_scene(std::filesystem::path(VKWATER_SOURCE_DIR) / "scenes/pool.json", {"water=null"});
    scene.camera.target = scene.camera.position - scene.sun.direction;
    scene.camera.fov_y_deg = 2.0;  // the disk (0.53 degrees across) covers many pixels
    Renderer renderer(context());
    const RenderResult result = renderer.render(scene, {kWidth, kHeight, true, fg::TimingMode::None});
    const float* centre = result.image.pixel(kWidth / 2, kHeight / 2);
    for (int c = 0; c < 3; ++c) {
        const double expected = scene.sky.radiance[c] + scene.sun.irradiance[c] / kSunDiskSolidAngle;
        // Same fp32 rounding budget as above (a division and an add on rounded inputs).
        EXPECT_NEAR(centre[c], expected, 1e-6 * expected) << "channel " << c;
    }
}

}  // namespace
}  // namespace vkw::test
