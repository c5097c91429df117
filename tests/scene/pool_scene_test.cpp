// scenes/pool.json loads with the values it states, omitted fields take their defaults, and
// an unreadable file is refused with the reason.
#include <cmath>
#include <numbers>

#include <gtest/gtest.h>

#include "engine/scene/scene_loader.hpp"
#include "tests/scene/scene_test_support.hpp"

namespace vkw {
namespace {

TEST(scene_pool, LoadsWithExpectedValues) {
    const Scene scene = load_scene(test::kSourceDir / "scenes/pool.json");
    EXPECT_EQ(scene.source, test::kSourceDir / "scenes/pool.json");
    EXPECT_FALSE(scene.description.empty());

    EXPECT_EQ(scene.camera.position, glm::dvec3(0.0, 1.2, 4.0));
    EXPECT_EQ(scene.camera.target, glm::dvec3(0.0, -1.5, -2.0));
    EXPECT_EQ(scene.camera.fov_y_deg, 60.0);
    EXPECT_EQ(scene.camera.near_plane, 0.05);
    EXPECT_EQ(scene.camera.far_plane, 500.0);
    EXPECT_EQ(scene.camera.exposure, 1.0);

    // elevation 80, azimuth 30: toward the sun (cos80 sin30, sin80, -cos80 cos30).
    const double el = 80.0 * std::numbers::pi / 180.0;
    const glm::dvec3 expected = -glm::dvec3(std::cos(el) * 0.5, std::sin(el), -std::cos(el) * std::sqrt(3.0) / 2.0);
    EXPECT_NEAR(scene.sun.direction.x, expected.x, 1e-15);
    EXPECT_NEAR(scene.sun.direction.y, expected.y, 1e-15);
    EXPECT_NEAR(scene.sun.direction.z, expected.z, 1e-15);
    EXPECT_EQ(scene.sun.irradiance, glm::dvec3(3.0));

    EXPECT_EQ(scene.sky.radiance, glm::dvec3(0.3, 0.45, 0.7));
    EXPECT_EQ(scene.floor.height, -1.5);
    EXPECT_EQ(scene.floor.albedo, glm::dvec3(0.6));
    EXPECT_EQ(scene.floor.half_extent, 10.0);

    ASSERT_TRUE(scene.water.has_value());
    EXPECT_EQ(scene.water->level, 0.0);
    EXPECT_EQ(scene.water->ior, 1.333);
    EXPECT_EQ(scene.water->grid_resolution, 1024u);
    EXPECT_FALSE(scene.water->depth.has_value());
    EXPECT_EQ(water_bottom(scene), -1.5);
    EXPECT_EQ(scene.medium.preset, "pure");
    EXPECT_TRUE(scene.receivers.empty());
}

TEST(scene_pool, WavesFocusNearTheFloor) {
    // docs/model.md section 5: first cusp under a vertical sun at d* = f - A, f = 1 / ((1 - 1/n) A k^2);
    // each of the two perpendicular sines focuses on its own axis.
    const Scene scene = load_scene(test::kSourceDir / "scenes/pool.json");
    const WaveSettings& waves = scene.water->waves;
    ASSERT_EQ(waves.model, WaveModel::Sum);
    ASSERT_EQ(waves.components.size(), 2u);
    const double depth = scene.water->level - scene.floor.height;
    for (const WaveComponent& wave : waves.components) {
        EXPECT_EQ(wave.wavelength, 0.5);
        EXPECT_EQ(wave.amplitude, 0.017);
        EXPECT_EQ(wave.steepness, 0.0);
        EXPECT_LT(wave.speed, 0.0);  // deep-water dispersion
        const double k = 2.0 * std::numbers::pi / wave.wavelength;
        const double focus = 1.0 / ((1.0 - 1.0 / scene.water->ior) * wave.amplitude * k * k) - wave.amplitude;
        EXPECT_NEAR(focus, 1.47, 0.01);
        EXPECT_NEAR(focus, depth, 0.05);
    }
    EXPECT_NEAR(waves.components[1].direction_deg - waves.components[0].direction_deg, 90.0, 0.0);
    EXPECT_GE(-scene.sun.direction.y, std::sin(75.0 * std::numbers::pi / 180.0));  // a high sun
}

TEST(scene_pool, FloorAndSkyRadianceAreOfTheSameOrder) {
    // docs/model.md section 1 without water: L_floor = rho (E_s cos(theta_s) + pi L_sky) / pi.
    const Scene scene = load_scene(test::kSourceDir / "scenes/pool.json");
    const double cos_theta = -scene.sun.direction.y;
    for (int c = 0; c < 3; ++c) {
        const double floor = scene.floor.albedo[c] * (scene.sun.irradiance[c] * cos_theta) / std::numbers::pi +
                             scene.floor.albedo[c] * scene.sky.radiance[c];
        const double ratio = floor / scene.sky.radiance[c];
        EXPECT_GT(ratio, 0.5) << "channel " << c;
        EXPECT_LT(ratio, 5.0) << "channel " << c;
    }
}

TEST(scene_defaults, OmittedFieldsTakeDocumentedDefaults) {
    const Scene scene = parse_scene(test::kMinimalScene, "minimal.json");
    EXPECT_EQ(scene.source, "minimal.json");
    EXPECT_EQ(scene.description, "");
    EXPECT_EQ(scene.camera.fov_y_deg, 60.0);
    EXPECT_EQ(scene.camera.near_plane, 0.05);
    EXPECT_EQ(scene.camera.far_plane, 500.0);
    EXPECT_EQ(scene.camera.exposure, 1.0);
    EXPECT_EQ(scene.sun.irradiance, glm::dvec3(1.0));
    EXPECT_EQ(scene.floor.height, -1.5);
    EXPECT_EQ(scene.floor.albedo, glm::dvec3(0.5));
    EXPECT_EQ(scene.floor.half_extent, 10.0);
    EXPECT_FALSE(scene.water.has_value());
    EXPECT_EQ(scene.medium.preset, "pure");
    EXPECT_EQ(scene.sky.model, SkyModel::Constant);
    EXPECT_TRUE(scene.receivers.empty());
    for (const EffectSettings& effect : scene.effects.settings) EXPECT_EQ(effect.mode, EffectMode::Auto);
}

TEST(scene_file, MissingFileNamesPathAndReason) {
    const std::string message = test::user_error_of([] { load_scene("/nonexistent/dir/scene.json"); });
    EXPECT_EQ(message, "cannot open scene file '/nonexistent/dir/scene.json': No such file or directory");
}

TEST(scene_file, DirectoryIsRefused) {
    const std::string message = test::user_error_of([] { load_scene(test::kSourceDir / "scenes"); });
    EXPECT_NE(message.find("cannot open scene file"), std::string::npos) << message;
    EXPECT_NE(message.find("Is a directory"), std::string::npos) << message;
}

}  // namespace
}  // namespace vkw
