// The water section and its waves: defaults, the three models, the steepness rule, and
// water without depth needing a floor below it.
#include <gtest/gtest.h>

#include "engine/scene/scene_loader.hpp"
#include "tests/scene/scene_test_support.hpp"

namespace vkw {
namespace {

Scene with_water(const std::string& water_json, const std::vector<std::string>& overrides = {}) {
    const std::string text = R"({ "camera": { "position": [0, 1, 3], "target": [0, 0, 0] },
                                  "sun": { "elevation_deg": 45 }, "sky": { "radiance": [1, 1, 1] },
                                  "water": )" +
                             water_json + "}";
    return parse_scene(text, "water.json", overrides);
}

std::string error_of(const std::string& water_json, const std::vector<std::string>& overrides = {}) {
    return test::user_error_of([&] { with_water(water_json, overrides); });
}

TEST(scene_water, EmptyObjectTakesTheDocumentedDefaults) {
    const Water water = *with_water("{}").water;
    EXPECT_EQ(water.level, 0.0);
    EXPECT_EQ(water.ior, 1.333);
    EXPECT_EQ(water.half_extent, 10.0);
    EXPECT_EQ(water.grid_resolution, 256u);
    EXPECT_EQ(water.time, 0.0);
    EXPECT_FALSE(water.depth.has_value());
    EXPECT_EQ(water.waves.model, WaveModel::Flat);
    EXPECT_EQ(water.waves.seed, 1u);
    EXPECT_FALSE(water.waves.allow_folding);
}

TEST(scene_water, DepthGivesTheVolumeItsOwnBottom) {
    const Scene scene = with_water(R"({ "level": 0.5, "depth": 3 })");
    EXPECT_EQ(water_bottom(scene), -2.5);
    EXPECT_EQ(water_bottom(with_water("{}")), -1.5);  // the default floor
    // Without depth, the floor must lie below the level.
    const std::string message = error_of(R"({ "level": -2 })");
    EXPECT_NE(message.find("water.json: water.level: -2 is not above floor.height = -1.5"), std::string::npos)
        << message;
    EXPECT_EQ(water_bottom(with_water(R"({ "level": -2, "depth": 1 })")), -3.0);
}

TEST(scene_water, InfiniteWaterMapsTheSquareOfItsReceivers) {
    // The default floor's square (10 m), then a receiver reaching 30 m out in -z.
    const Water water = *with_water(R"({ "half_extent": "infinite" })").water;
    EXPECT_TRUE(water.infinite);
    EXPECT_EQ(water.half_extent, 10.0);
    EXPECT_EQ(water.screen_mesh_cell_pixels(), kDefaultInfiniteWaterCellPixels);  // never the uniform mesh
    const std::string text = R"({ "camera": { "position": [0, 1, 3], "target": [0, 0, 0] },
                                  "sun": { "elevation_deg": 45 }, "sky": { "radiance": [1, 1, 1] },
                                  "water": { "half_extent": "infinite", "mesh_cell_pixels": 4 },
                                  "receivers": [{ "type": "box", "half_size": [1, 1, 1],
                                                  "translation": [0, -1, -29] }] })";
    const Scene scene = parse_scene(text, "water.json");
    EXPECT_EQ(scene.water->half_extent, 30.0);
    EXPECT_EQ(scene.water->screen_mesh_cell_pixels(), 4u);
    // The square drawn holds all the camera sees: its own distance from the centre plus its far plane.
    EXPECT_EQ(water_drawn_half_extent(scene), 3.0 + scene.camera.far_plane);
    // A number is a square, as before.
    EXPECT_FALSE(with_water(R"({ "half_extent": 4 })").water->infinite);
}

TEST(scene_water, SumOfSinesAndGerstnerWaves) {
    const Water water = *with_water(R"({ "seed": 9, "time": 2.5, "waves": { "model": "sum", "components": [
        { "amplitude": 0.1, "wavelength": 2, "direction_deg": 30, "phase_deg": 45, "steepness": 0.5, "speed": 1.5 },
        { "amplitude": 0.05, "wavelength": 1 } ] } })")
                             .water;
    ASSERT_EQ(water.waves.model, WaveModel::Sum);
    ASSERT_EQ(water.waves.components.size(), 2u);
    const WaveComponent& first = water.waves.components[0];
    EXPECT_EQ(first.amplitude, 0.1);
    EXPECT_EQ(first.wavelength, 2.0);
    EXPECT_EQ(first.direction_deg, 30.0);
    EXPECT_EQ(first.phase_deg, 45.0);
    EXPECT_EQ(first.steepness, 0.5);
    EXPECT_EQ(first.speed, 1.5);
    const WaveComponent& second = water.waves.components[1];
    EXPECT_EQ(second.direction_deg, 0.0);
    EXPECT_EQ(second.steepness, 0.0);
    EXPECT_LT(second.speed, 0.0);  // omitted: deep-water dispersion
    EXPECT_EQ(water.waves.seed, 9u);
    EXPECT_EQ(water.time, 2.5);
}

TEST(scene_water, SteepnessSumAboveOneNeedsAllowFolding) {
    const std::string waves = R"({ "waves": { "model": "sum", "components": [
        { "amplitude": 0.1, "wavelength": 2, "steepness": 0.75 },
        { "amplitude": 0.1, "wavelength": 3, "steepness": 0.5 } ] } })";
    const std::string message = error_of(waves);
    EXPECT_NE(message.find("water.waves.components: the Gerstner steepness values sum to 1.25"), std::string::npos)
        << message;
    EXPECT_NE(message.find("(accepted: sum of steepness <= 1, or allow_folding: true)"), std::string::npos) << message;
    EXPECT_TRUE(with_water(waves, {"water.waves.allow_folding=true"}).water->waves.allow_folding);
    // Exactly 1 is allowed.
    EXPECT_NO_THROW(with_water(waves, {"water.waves.components[1].steepness=0.25"}));
}

TEST(scene_water, FftOcean) {
    const Water water = *with_water(R"({ "waves": { "model": "fft", "resolution": 512, "patch_size": 100,
        "wind_speed": 12, "wind_direction_deg": -45, "spectrum": "jonswap", "fetch": 20000,
        "amplitude_scale": 0.5, "choppiness": 1.2 } })")
                             .water;
    const FftOceanSettings& ocean = water.waves.ocean;
    EXPECT_EQ(water.waves.model, WaveModel::FftOcean);
    EXPECT_EQ(ocean.resolution, 512u);
    EXPECT_EQ(ocean.patch_size, 100.0);
    EXPECT_EQ(ocean.wind_speed, 12.0);
    EXPECT_EQ(ocean.wind_direction_deg, -45.0);
    EXPECT_EQ(ocean.spectrum, OceanSpectrum::Jonswap);
    EXPECT_EQ(ocean.fetch, 20000.0);
    EXPECT_EQ(ocean.amplitude_scale, 0.5);
    EXPECT_EQ(ocean.choppiness, 1.2);
    const FftOceanSettings defaults;
    const FftOceanSettings plain = with_water(R"({ "waves": { "model": "fft" } })").water->waves.ocean;
    EXPECT_EQ(plain.resolution, defaults.resolution);
    EXPECT_EQ(plain.spectrum, OceanSpectrum::Phillips);
    EXPECT_NE(error_of(R"({ "waves": { "model": "fft", "fetch": 1000 } })")
                  .find("water.waves.fetch: is only used by the jonswap spectrum"),
              std::string::npos);
}

TEST(scene_water, FieldsOfAnotherModelAreRefused) {
    EXPECT_NE(
        error_of(R"({ "waves": { "model": "fft", "components": [] } })").find("water.waves.components: unknown field"),
        std::string::npos);
    EXPECT_NE(error_of(R"({ "waves": { "components": [{ "amplitude": 1, "wavelength": 1 }] } })")
                  .find("water.waves.model: missing (components is given) (accepted: one of flat, sum, fft)"),
              std::string::npos);
    EXPECT_NE(error_of(R"({ "waves": { "model": "sum" } })").find("water.waves.components: missing required field"),
              std::string::npos);
}

TEST(scene_water, NonFiniteOverridesAreRefusedWithTheRange) {
    const std::string message = error_of("{}", {"water.ior=nan"});
    EXPECT_EQ(message,
              "water.json: water.ior: string \"nan\" is not a finite number (accepted: 1 <= value <= 2) "
              "[from override 'water.ior=nan']");
    EXPECT_NE(
        error_of("{}", {"water.grid_resolution=inf"}).find("(accepted: an integer, 2 <= value <= 4096 cells per side)"),
        std::string::npos);
}

}  // namespace
}  // namespace vkw
