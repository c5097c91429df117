// The smaller sections: the sky's gradient model, the camera's direction form, effect
// settings named as the frame graph names its effects, and overrides into arrays.
#include <cmath>

#include <gtest/gtest.h>

#include "engine/framegraph/frame_needs.hpp"
#include "engine/scene/scene_loader.hpp"
#include "tests/scene/scene_test_support.hpp"

namespace vkw {
namespace {

Scene with(const std::vector<std::string>& overrides) {
    return parse_scene(test::kMinimalScene, "min.json", overrides);
}

TEST(scene_sky, GradientFormulaAndItsAverage) {
    const Sky sky = with({"sky.radiance=null", "sky.model=gradient", "sky.zenith=[0.1,0.2,0.4]",
                          "sky.horizon=[0.5,0.6,0.7]", "sky.exponent=2"})
                        .sky;
    EXPECT_EQ(sky.model, SkyModel::Gradient);
    EXPECT_EQ(sky.ground, sky.horizon);  // default: the horizon continued downward
    EXPECT_EQ(sky_radiance(sky, {0.0, 1.0, 0.0}), sky.zenith);
    EXPECT_EQ(sky_radiance(sky, {1.0, 0.0, 0.0}), sky.horizon);
    EXPECT_EQ(sky_radiance(sky, {0.0, -1.0, 0.0}), sky.ground);
    // dir.y = 0.5, exponent 2: weight 0.25 on the zenith.
    const glm::dvec3 mid = sky_radiance(sky, {std::sqrt(0.75), 0.5, 0.0});
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(mid[c], 0.75 * sky.horizon[c] + 0.25 * sky.zenith[c], 1e-15);
    // Closed-form average against a midpoint quadrature of 2 * integral of L(mu) mu dmu.
    glm::dvec3 quadrature(0.0);
    const int steps = 100000;
    for (int i = 0; i < steps; ++i) {
        const double mu = (i + 0.5) / steps;
        quadrature += 2.0 * sky_radiance(sky, {std::sqrt(1.0 - mu * mu), mu, 0.0}) * mu / double(steps);
    }
    const glm::dvec3 average = sky_average_radiance(sky);
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(average[c], quadrature[c], 1e-9);
    // A constant sky's average is its radiance.
    EXPECT_EQ(sky_average_radiance(with({}).sky), glm::dvec3(0.3, 0.4, 0.5));
}

TEST(scene_sky, GradientFieldsBelongToTheGradientModel) {
    const std::string message = test::user_error_of([] { with({"sky.zenith=[1,1,1]"}); });
    EXPECT_NE(message.find("sky.zenith: not a field of this model (it belongs to the gradient sky: add "
                           "\"model\": \"gradient\")"),
              std::string::npos)
        << message;
    EXPECT_NE(message.find("(accepted: model, radiance)"), std::string::npos) << message;
    // And the constant sky's field under the gradient model.
    const std::string other = test::user_error_of([] { with({"sky.model=gradient", "sky.radiance=[1,1,1]"}); });
    EXPECT_NE(other.find("sky.radiance: not a field of this model (it belongs to the constant sky"), std::string::npos)
        << other;
}

TEST(scene_camera, DirectionFormLooksAlongTheNormalisedVector) {
    const Camera camera = with({"camera.target=null", "camera.direction=[0,-3,-4]"}).camera;
    const glm::dvec3 expected = camera.position + glm::dvec3(0.0, -0.6, -0.8);
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(camera.target[c], expected[c], 1e-15);
    EXPECT_NE(test::user_error_of([] {
                  with({"camera.target=null", "camera.direction=[0,0,0]"});
              }).find("camera.direction: [0, 0, 0] has no direction (accepted: a non-zero vector)"),
              std::string::npos);
}

TEST(scene_effects, NamedExactlyAsTheFrameGraphNamesThem) {
    for (std::size_t i = 0; i < kEffectCount; ++i) {
        const auto effect = static_cast<Effect>(i);
        const std::string name = effect_name(effect);
        SCOPED_TRACE(name);
        const Scene scene = with({"effects." + name + ".mode=off"});
        for (std::size_t j = 0; j < kEffectCount; ++j) {
            EXPECT_EQ(scene.effects.settings[j].mode, j == i ? EffectMode::Off : EffectMode::Auto);
        }
        EXPECT_EQ(with({"effects." + name + ".mode=on"}).effects[effect].mode, EffectMode::On);
        EXPECT_EQ(with({"effects." + name + "={}"}).effects[effect].mode, EffectMode::Auto);
    }
}

// effects.caustics' settings: their defaults (scenes/README.md), each read, and each refused
// outside its range naming the field and what is accepted.
TEST(scene_effects, CausticSettingsDefaultsReadAndRanges) {
    const CausticSettings defaults = with({}).effects.caustics;
    EXPECT_TRUE(defaults.analytic_flat);
    EXPECT_EQ(defaults.sub_photons, 1u);
    EXPECT_FALSE(defaults.jitter);
    EXPECT_EQ(defaults.kernel, CausticKernel::Adaptive);
    EXPECT_EQ(defaults.map_scale, 1.0);
    EXPECT_EQ(with({"effects.caustics.map_scale=2"}).effects.caustics.map_scale, 2.0);
    EXPECT_NE(test::user_error_of([] { with({"effects.caustics.map_scale=8"}); }).find("effects.caustics.map_scale"),
              std::string::npos);

    const CausticSettings set = with({"effects.caustics.analytic_flat=false", "effects.caustics.sub_photons=4",
                                      "effects.caustics.jitter=true", "effects.caustics.kernel=bilinear"})
                                    .effects.caustics;
    EXPECT_FALSE(set.analytic_flat);
    EXPECT_EQ(set.sub_photons, 4u);
    EXPECT_TRUE(set.jitter);
    EXPECT_EQ(set.kernel, CausticKernel::Bilinear);

    auto error_with = [](const std::string& override) { return test::user_error_of([&] { with({override}); }); };
    EXPECT_NE(error_with("effects.caustics.kernel=gaussian")
                  .find("effects.caustics.kernel: unknown value \"gaussian\" "
                        "(accepted: one of adaptive, bilinear, footprint)"),
              std::string::npos)
        << error_with("effects.caustics.kernel=gaussian");
    const std::string sub = error_with("effects.caustics.sub_photons=9");
    EXPECT_NE(sub.find("effects.caustics.sub_photons"), std::string::npos) << sub;
    EXPECT_NE(sub.find("8"), std::string::npos) << sub;

    // effects.caustic_blur.radius: 0 by default (no blur), texels in [0, 4].
    EXPECT_EQ(with({}).effects.caustic_blur.radius, 0.0);
    EXPECT_EQ(with({"effects.caustic_blur.radius=1.5"}).effects.caustic_blur.radius, 1.5);
    const std::string radius = error_with("effects.caustic_blur.radius=5");
    EXPECT_NE(radius.find("effects.caustic_blur.radius"), std::string::npos) << radius;
    EXPECT_NE(radius.find("texels"), std::string::npos) << radius;
}

TEST(scene_overrides, ArrayElementsByIndex) {
    const std::string text = R"({ "camera": { "position": [0, 1, 3], "target": [0, 0, 0] },
        "sun": { "elevation_deg": 45 }, "sky": { "radiance": [1, 1, 1] },
        "receivers": [{ "type": "sphere", "radius": 1 }, { "type": "sphere", "radius": 2 }] })";
    const Scene scene = parse_scene(text, "r.json", {"receivers[1].radius=0.5", "sky.radiance[2]=3"});
    EXPECT_NEAR(scene.receivers[1].mesh.bounds_max.y, 0.5, 1e-7);
    EXPECT_EQ(scene.sky.radiance, glm::dvec3(1.0, 1.0, 3.0));
    EXPECT_EQ(parse_scene(text, "r.json", {"receivers[0]=null"}).receivers.size(), 1u);

    const std::string past_end = test::user_error_of([&] { parse_scene(text, "r.json", {"receivers[2].radius=1"}); });
    EXPECT_NE(past_end.find("r.json: receivers[2]: override 'receivers[2].radius=1' indexes past the end of an array "
                            "of 2 elements (accepted: an index below 2)"),
              std::string::npos)
        << past_end;
    const std::string not_array = test::user_error_of([&] { parse_scene(text, "r.json", {"camera[0]=1"}); });
    EXPECT_NE(not_array.find("camera: override 'camera[0]=1' indexes a value that is not an array"), std::string::npos)
        << not_array;
    const std::string bad_syntax = test::user_error_of([&] { parse_scene(text, "r.json", {"receivers[x].radius=1"}); });
    EXPECT_NE(bad_syntax.find("malformed [index]"), std::string::npos) << bad_syntax;
    // An error inside an overridden element names the override.
    const std::string range = test::user_error_of([&] { parse_scene(text, "r.json", {"receivers[0].radius=0"}); });
    EXPECT_EQ(range,
              "r.json: receivers[0].radius: 0 is out of range (accepted: 0 < value <= 1e+05 m) "
              "[from override 'receivers[0].radius=0']");
}

}  // namespace
}  // namespace vkw

namespace vkw {
namespace {

// floor.tiles: the grout within grout / 2 of every multiple of the side, in x and in z, on both
// sides of 0; the floor's albedo elsewhere.
TEST(scene_floor, TilesPutGroutOnTheMultiplesOfTheSide) {
    const FloorPlane floor =
        with({"floor.albedo=[0.6,0.7,0.8]", "floor.tiles={\"side\":0.5,\"grout\":0.02,\"grout_albedo\":[0.1,0.2,0.3]}"})
            .floor;
    const glm::dvec3 tile(0.6, 0.7, 0.8), grout(0.1, 0.2, 0.3);
    EXPECT_EQ(floor.albedo_at(0.25, 0.25), tile);  // a tile's centre
    EXPECT_EQ(floor.albedo_at(-0.25, 1.75), tile);
    EXPECT_EQ(floor.albedo_at(0.0, 0.25), grout);     // on the edge x = 0
    EXPECT_EQ(floor.albedo_at(0.25, -1.0), grout);    // on the edge z = -1
    EXPECT_EQ(floor.albedo_at(0.509, 0.25), grout);   // 9 mm from x = 0.5: within the 10 mm half-width
    EXPECT_EQ(floor.albedo_at(0.511, 0.25), tile);    // 11 mm from it
    EXPECT_EQ(floor.albedo_at(-0.491, 0.25), grout);  // 9 mm from x = -0.5
    EXPECT_EQ(floor.albedo_at(-0.489, 0.25), tile);
    // Without tiles, and with grout 0 (no lines at all), one albedo everywhere.
    EXPECT_EQ(with({}).floor.albedo_at(0.0, 0.0), with({}).floor.albedo);
    const FloorPlane no_grout = with({"floor.tiles={\"side\":0.5,\"grout\":0}"}).floor;
    EXPECT_EQ(no_grout.albedo_at(0.0, 0.0), no_grout.albedo);
    // The defaults: 25 cm tiles, 1 cm grout.
    const FloorPlane defaults = with({"floor.tiles={}"}).floor;
    ASSERT_TRUE(defaults.tiles);
    EXPECT_EQ(defaults.tiles->side, 0.25);
    EXPECT_EQ(defaults.tiles->grout, 0.01);
}

TEST(scene_floor, GroutAsWideAsATileIsRefused) {
    const std::string message = test::user_error_of([] { with({"floor.tiles={\"side\":0.25,\"grout\":0.25}"}); });
    EXPECT_NE(
        message.find("floor.tiles.grout: 0.25 m is not below the tiles' side 0.25 m (accepted: 0 <= grout < side)"),
        std::string::npos)
        << message;
    EXPECT_NE(test::user_error_of([] { with({"floor.tiles={\"side\":0}"}); }).find("floor.tiles.side"),
              std::string::npos);
    EXPECT_NE(test::user_error_of([] { with({"floor.tiles={\"sied\":1}"}); }).find("floor.tiles.sied"),
              std::string::npos);
}

}  // namespace
}  // namespace vkw
