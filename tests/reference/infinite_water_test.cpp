// Infinite water in the CPU reference (docs/model.md section 1, "Infinite water"): no edge, the
// waves traced out to the far field and the flat mean level beyond it, and under it a water body
// whose rays that meet no receiver run on to its bottom.
#include "engine/scene/scene_loader.hpp"
#include "tools/reference/optics.hpp"
#include "tools/reference/water_transport.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <string>

namespace vkw::ref {
namespace {

// One sine along x (A = 0.05 m, wavelength 2 m) over a floor 1.5 m down whose square is 50 m wide,
// the camera 2 m up; `half_extent` is the water's ("infinite" or a number).
Scene sine_over_a_small_floor(const std::string& half_extent, const std::string& floor_albedo = "[0.6, 0.5, 0.4]") {
    return parse_scene(R"({
      "camera": {"position": [0, 2, 0], "target": [0, 0, -1], "far": 100000},
      "sun": {"elevation_deg": 40, "azimuth_deg": 90, "irradiance": [3, 2, 1]},
      "sky": {"radiance": [0.3, 0.45, 0.7]},
      "floor": {"height": -1.5, "albedo": )" +
                           floor_albedo +
                           R"(, "half_extent": 25},
      "water": {"level": 0, "half_extent": )" +
                           half_extent + R"(,
                "waves": {"model": "sum", "components": [{"amplitude": 0.05, "wavelength": 2, "direction_deg": 0}]}},
      "medium": {"sigma_a": [0.45, 0.06, 0.02], "sigma_s": [0.17, 0.2, 0.234], "g": 0.9}
    })",
                       "infinite.json");
}

// The unit ray from `origin` whose crossing with the level y = 0 lies `reach` metres away
// horizontally, along `heading` (unit, horizontal).
Ray ray_to_level(const glm::dvec3& origin, double reach, const glm::dvec3& heading) {
    return {origin, glm::normalize(glm::dvec3(heading.x * reach, -origin.y, heading.z * reach))};
}

TEST(reference_infinite_water, TheLoaderGivesItTheReceiversSquareForItsMaps) {
    const Scene scene = sine_over_a_small_floor(R"("infinite")");
    ASSERT_TRUE(scene.water->infinite);
    EXPECT_EQ(scene.water->half_extent, 25.0);  // the floor's: photons and beams are traced over it
}

TEST(reference_infinite_water, BeyondTheFarFieldARayMeetsTheFlatLevel) {
    const WaterTransport transport(sine_over_a_small_floor(R"("infinite")"));
    const glm::dvec3 eye(0.0, 2.0, 0.0);
    // Along -z the sine's crests run across the ray; 1.5 times the far field away.
    const Ray ray = ray_to_level(eye, 1.5 * kInfiniteWaterFarField, {0.0, 0.0, -1.0});
    const auto hit = transport.water_surface_hit(ray);
    ASSERT_TRUE(hit.has_value());
    // The crossing with y = 0 exactly (a division and a few roundings: 1e-15 relative).
    const double to_level = eye.y / -ray.direction.y;
    EXPECT_NEAR(hit->distance, to_level, 1e-12 * to_level);
    EXPECT_EQ(hit->normal, glm::dvec3(0.0, 1.0, 0.0));
}

TEST(reference_infinite_water, WithinTheFarFieldTheWavesAreTracedPastTheReceiversSquare) {
    const Scene scene = sine_over_a_small_floor(R"("infinite")");
    const WaterTransport transport(scene);
    const glm::dvec3 eye(0.0, 2.0, 0.0);
    // Along +x, across the crests, 200 m away: far outside the floor's 25 m square, inside the far field.
    const Ray ray = ray_to_level(eye, 200.0, {1.0, 0.0, 0.0});
    const auto hit = transport.water_surface_hit(ray);
    ASSERT_TRUE(hit.has_value());
    const glm::dvec3 p = ray.origin + hit->distance * ray.direction;
    // On the sine (a heightfield): y = A sin(k x), bisected to 1e-12 m along a ray that falls 1 in 100.
    const double k = 2.0 * std::acos(-1.0) / 2.0;
    EXPECT_NEAR(p.y, 0.05 * std::sin(k * p.x), 1e-9);
    EXPECT_GT(p.x, 150.0);
    // The normal is the sine's, tilted along x, not the level's.
    EXPECT_NEAR(hit->normal.x,
                -0.05 * k * std::cos(k * p.x) / std::sqrt(1.0 + std::pow(0.05 * k * std::cos(k * p.x), 2)), 1e-9);
    // The same ray over water of a 25 m square misses it.
    const WaterTransport finite(sine_over_a_small_floor("25"));
    EXPECT_FALSE(finite.water_surface_hit(ray).has_value());
}

TEST(reference_infinite_water, ARefractedRayThatMeetsNoReceiverRunsToTheBottom) {
    // Seen from 2 m up at 30 degrees below the horizon, 1000 m out along z (no floor under it),
    // the pixel of infinite water must equal the same pixel over a black floor at the bottom's
    // height: the same reflection, the same path through the water to y = -1.5, nothing lit
    // behind it. Flat water (the sine's amplitude does not matter to this rule; the flat case
    // has one refracted path per pixel).
    auto flat = [](const std::string& half_extent, const std::string& albedo) {
        Scene scene = sine_over_a_small_floor(half_extent, albedo);
        scene.water->waves = WaveSettings{};
        return scene;
    };
    const Scene infinite_scene = flat(R"("infinite")", "[0.6, 0.5, 0.4]");
    const Scene black_floor_scene = flat("25", "[0, 0, 0]");
    const WaterTransport infinite(infinite_scene);  // keeps a reference to its scene
    const WaterTransport black_floor(black_floor_scene);
    const glm::dvec3 view =
        glm::normalize(glm::dvec3(0.0, -std::sin(0.5235987755982988), -std::cos(0.5235987755982988)));
    const PixelRadiance beyond = infinite.trace_camera_ray({{0.0, 2.0, 1000.0}, view});
    const PixelRadiance over_black = black_floor.trace_camera_ray({{0.0, 2.0, 0.0}, view});
    for (int c = 0; c < 3; ++c) {
        // The in-scatter carries the pixel's water: not 0 (the rule before infinite water).
        ASSERT_GT(beyond.in_scatter[c], 0.0) << "channel " << c;
        // The two paths differ only in the horizontal coordinates of their points, which the
        // flat model does not read, and in the roundings of coordinates 1000 m out: 1e-12 relative.
        EXPECT_NEAR(beyond.radiance[c], over_black.radiance[c], 1e-12 * over_black.radiance[c]) << "channel " << c;
        EXPECT_NEAR(beyond.in_scatter[c], over_black.in_scatter[c], 1e-12 * over_black.in_scatter[c])
            << "channel " << c;
    }
}

// The flat version of the scene above, with `half_extent` for the water and `albedo` for the floor.
Scene flat_over_a_small_floor(const std::string& half_extent, const std::string& albedo) {
    Scene scene = sine_over_a_small_floor(half_extent, albedo);
    scene.water->waves = WaveSettings{};
    return scene;
}

TEST(reference_infinite_water, ACameraRayInTheWaterThatMeetsNothingRunsToTheBottom) {
    // A camera 1 m under the water, 1000 m out along z (no floor under it), looking 10 degrees
    // down: the pixel must equal the same ray from over a black floor at the bottom's height, as
    // for the refracted ray above. Before this rule it was black.
    const Scene infinite_scene = flat_over_a_small_floor(R"("infinite")", "[0.6, 0.5, 0.4]");
    const Scene black_floor_scene = flat_over_a_small_floor("25", "[0, 0, 0]");
    const WaterTransport infinite(infinite_scene);
    const WaterTransport black_floor(black_floor_scene);
    const double down = 10.0 * std::acos(-1.0) / 180.0;
    const glm::dvec3 view(0.0, -std::sin(down), -std::cos(down));
    const PixelRadiance beyond = infinite.trace_camera_ray({{0.0, -1.0, 1000.0}, view});
    const PixelRadiance over_black = black_floor.trace_camera_ray({{0.0, -1.0, 0.0}, view});
    for (int c = 0; c < 3; ++c) {
        ASSERT_GT(beyond.radiance[c], 0.0) << "channel " << c;
        // As above: only the horizontal coordinates differ, 1e-12 relative.
        EXPECT_NEAR(beyond.radiance[c], over_black.radiance[c], 1e-12 * over_black.radiance[c]) << "channel " << c;
        EXPECT_NEAR(beyond.in_scatter[c], over_black.in_scatter[c], 1e-12 * over_black.in_scatter[c])
            << "channel " << c;
    }
}

TEST(reference_infinite_water, AGrazingRayInTheWaterEndsAtTheFarField) {
    // 1e-6 rad under the horizon the bottom, 0.5 m below, lies 500 km away: the run ends at the
    // far field, 2000 m out horizontally, and brings exactly the in-scatter of that segment
    // (docs/model.md section 6's closed form), finite.
    const Scene scene = flat_over_a_small_floor(R"("infinite")", "[0.6, 0.5, 0.4]");
    const WaterTransport transport(scene);
    const double down = 1e-6;
    const glm::dvec3 view(0.0, -std::sin(down), -std::cos(down));
    const PixelRadiance pixel = transport.trace_camera_ray({{0.0, -1.0, 1000.0}, view});
    const double ior = scene.water->ior;
    const glm::dvec3 refracted_sun = *refract(scene.sun.direction, {0.0, 1.0, 0.0}, 1.0 / ior);
    const double cos_s = -scene.sun.direction.y;
    const glm::dvec3 e_perp0 =
        scene.sun.irradiance * (cos_s * (1.0 - fresnel_reflectance(cos_s, 1.0, ior)) / -refracted_sun.y);
    const double run = kInfiniteWaterFarField / std::cos(down);
    for (int c = 0; c < 3; ++c) {
        const double expected = water_path_radiance({scene.medium.sigma_s[c], scene.medium.sigma_t()[c], scene.medium.g,
                                                     1.0, run, view, refracted_sun, e_perp0[c], 0.0});
        ASSERT_GT(expected, 0.0);
        // The same function of the same inputs, up to the roundings of the run: 1e-12 relative.
        EXPECT_NEAR(pixel.radiance[c], expected, 1e-12 * expected) << "channel " << c;
    }
}

}  // namespace
}  // namespace vkw::ref
