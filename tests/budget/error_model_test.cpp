// The budget's error table is the measured one (docs/sweeps/budget_error_terms.csv, the largest
// excess of each knob's value over its scenes; the caustic knobs' per unit of each scene's caustic
// visibility), and the prediction adds its terms and names the largest.
#include "tools/vkwater/budget/error_model.hpp"

#include "engine/scene/scene_loader.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>

namespace vkw::budget {
namespace {

TEST(BudgetErrorModel, TableIsTheLargestMeasuredExcessOfEachKnob) {
    std::ifstream csv(std::filesystem::path(VKWATER_SOURCE_DIR) / "docs/sweeps/budget_error_terms.csv");
    ASSERT_TRUE(csv) << "docs/sweeps/budget_error_terms.csv (tools/benchmarks/budget_error_terms.sh)";
    std::string line;
    while (std::getline(csv, line) && line.rfind('#', 0) == 0) {
        // where the figures come from (tools/benchmarks/budget_error_terms.sh), before the header
    }
    ASSERT_EQ(line, "scene,knob,value,rel_mse,excess");
    std::map<std::pair<std::string, double>, double> largest;
    std::map<std::string, int> scenes_per_knob;
    while (std::getline(csv, line)) {
        std::istringstream fields(line);
        std::string scene, knob, value, rel_mse, excess;
        std::getline(fields, scene, ',');
        std::getline(fields, knob, ',');
        std::getline(fields, value, ',');
        std::getline(fields, rel_mse, ',');
        std::getline(fields, excess, ',');
        const auto key = std::make_pair(knob, std::stod(value));
        // The caustic knobs' entries are weights per unit of caustic visibility (quality.hpp).
        const bool caustic =
            knob == "photon_grid_fraction" || knob == "bilinear_kernel" || knob == "map_scale_fraction";
        const double measured =
            caustic ? std::stod(excess) / caustic_visibility(load_scene(std::filesystem::path(VKWATER_SOURCE_DIR) /
                                                                        "scenes" / (scene + ".json")))
                    : std::stod(excess);
        // Twice the rows and more samples are gains: the table keeps the largest one (the most
        // negative), so that a lower scale's term is not underestimated.
        const bool gain = (knob == "render_scale" && key.second > 1.0) || knob == "samples_per_pixel";
        const bool first = !largest.count(key);
        largest[key] = first ? measured : gain ? std::min(largest[key], measured) : std::max(largest[key], measured);
    }
    ASSERT_GE(largest.size(), 15u);
    const std::map<std::string, Knob> knobs = {{"render_scale", Knob::RenderScale},
                                               {"photon_grid_fraction", Knob::PhotonGridFraction},
                                               {"mesh_resolution", Knob::MeshResolution},
                                               {"godray_grid", Knob::GodrayGrid},
                                               {"lookup_steps", Knob::LookupSteps},
                                               {"bilinear_kernel", Knob::BilinearKernel},
                                               {"map_scale_fraction", Knob::MapScaleFraction},
                                               {"samples_per_pixel", Knob::SamplesPerPixel},
                                               {"second_layer", Knob::SecondLayer},
                                               {"shadow_texels", Knob::ShadowTexels},
                                               {"terrain_fraction", Knob::TerrainFraction},
                                               {"reflection_lookup", Knob::ReflectionLookup},
                                               {"refraction_lookup", Knob::RefractionLookup}};
    for (const auto& [key, excess] : largest) {
        ASSERT_TRUE(knobs.count(key.first)) << key.first;
        if (key.first == "godray_grid" && key.second > 64) continue;  // finer than the table: 0 by definition
        // The table holds the file's figures (over the visibility) to 6 significant digits.
        EXPECT_NEAR(error_term(knobs.at(key.first), key.second), excess, 1e-5 * std::abs(excess) + 1e-12)
            << key.first << " " << key.second;
    }
}

// Turning the refraction view's second layer off costs what the table measured, where the scene
// has the layer; a scene without it has no such term.
TEST(BudgetErrorModel, TheSecondLayerOffCostsItsMeasuredExcess) {
    Quality top{1.0, 1024, 256, 64};
    top.lookup_steps = 64;
    top.reflection_lookup = top.refraction_lookup = true;  // the layer is the refraction view's
    top.second_layer = true;
    EXPECT_EQ(predict_error(top, top).excess, 0.0);
    Quality off = top;
    off.second_layer = false;
    const ErrorPrediction prediction = predict_error(off, top);
    EXPECT_GT(error_term(Knob::SecondLayer, 0.0), 0.0) << "the sweep measured the layer off as no loss";
    EXPECT_DOUBLE_EQ(prediction.excess, error_term(Knob::SecondLayer, 0.0));
    EXPECT_EQ(prediction.dominant, "refraction second layer");
    EXPECT_EQ(error_term(Knob::SecondLayer, 1.0), 0.0);
    Quality without{1.0, 1024, 256, 64};
    EXPECT_EQ(predict_error(without, without).excess, 0.0);

    // Below the scene's lookup steps the layer finds nothing (its march takes a quarter of them):
    // the steps' term holds its loss, and turning it off there costs nothing more.
    for (uint32_t steps : {16u, 8u}) {
        Quality fewer = top;
        fewer.lookup_steps = steps;
        Quality fewer_off = fewer;
        fewer_off.second_layer = false;
        EXPECT_EQ(predict_error(fewer_off, top).excess, predict_error(fewer, top).excess) << steps << " steps";
        EXPECT_DOUBLE_EQ(predict_error(fewer, top).excess, error_term(Knob::LookupSteps, steps));
    }
}

// A smaller sun shadow map costs what the table measured below the scene's own map.
TEST(BudgetErrorModel, ASmallerShadowMapCostsItsMeasuredExcess) {
    Quality top{1.0, 1024, 256, 64};
    top.shadow_texels = 1024;
    Quality smaller = top;
    smaller.shadow_texels = 256;
    EXPECT_GT(error_term(Knob::ShadowTexels, 256), error_term(Knob::ShadowTexels, 512));
    EXPECT_GT(error_term(Knob::ShadowTexels, 512), 0.0);
    EXPECT_EQ(error_term(Knob::ShadowTexels, 2048), 0.0) << "finer than the table: nothing lost";
    EXPECT_DOUBLE_EQ(predict_error(smaller, top).excess, error_term(Knob::ShadowTexels, 256));
    EXPECT_EQ(predict_error(smaller, top).dominant, "sun shadow map");
    // From a scene's own 512, 256 costs the difference.
    Quality own = top;
    own.shadow_texels = 512;
    EXPECT_DOUBLE_EQ(predict_error(smaller, own).excess,
                     error_term(Knob::ShadowTexels, 256) - error_term(Knob::ShadowTexels, 512));
}

// A coarser terrain costs what the table measured at that fraction of the scene's own cells.
TEST(BudgetErrorModel, ACoarserTerrainCostsItsMeasuredExcess) {
    Quality top{1.0, 512, 256, 64};
    top.terrain_fraction = 1.0;
    EXPECT_EQ(predict_error(top, top).excess, 0.0);
    Quality quarter = top;
    quarter.terrain_fraction = 0.25;
    EXPECT_GT(error_term(Knob::TerrainFraction, 0.25), 0.0);
    EXPECT_GE(error_term(Knob::TerrainFraction, 0.25), error_term(Knob::TerrainFraction, 0.5));
    EXPECT_DOUBLE_EQ(predict_error(quarter, top).excess, error_term(Knob::TerrainFraction, 0.25));
    EXPECT_EQ(predict_error(quarter, top).dominant, "terrain detail");
}

TEST(BudgetErrorModel, TheScenesOwnSettingsAddNothing) {
    const Quality top{1.0, 1024, 256, 64};
    const ErrorPrediction none = predict_error(top, top);
    EXPECT_EQ(none.excess, 0.0);
    EXPECT_EQ(none.dominant, "");
}

TEST(BudgetErrorModel, TermsAddAndTheLargestIsNamed) {
    const Quality top{1.0, 1024, 256, 64};
    const Quality lower{0.5, 256, 128, 0};
    const double expected = error_term(Knob::RenderScale, 0.5) + error_term(Knob::PhotonGridFraction, 0.25) +
                            error_term(Knob::MeshResolution, 128) +
                            (error_term(Knob::GodrayGrid, 0) - error_term(Knob::GodrayGrid, 64));
    const ErrorPrediction prediction = predict_error(lower, top);
    EXPECT_DOUBLE_EQ(prediction.excess, expected);
    EXPECT_EQ(prediction.dominant, "resolution scale");
    // Each knob alone costs error, and the lower step more than the higher one.
    EXPECT_GT(error_term(Knob::RenderScale, 0.25), error_term(Knob::RenderScale, 0.5));
    EXPECT_GT(error_term(Knob::RenderScale, 0.5), error_term(Knob::RenderScale, 0.75));
    EXPECT_GT(error_term(Knob::PhotonGridFraction, 0.125), error_term(Knob::PhotonGridFraction, 0.5));
    EXPECT_GT(error_term(Knob::MeshResolution, 64), error_term(Knob::MeshResolution, 128));
}

// The resolution term follows the rows rendered: at the table's own 300 rows it is the table's
// entry; at an output of 600 rows the same scale renders twice the rows, and costs the error between
// the table's 1x and 2x, less than at 300; between steps it is interpolated in log2 of the rows.
TEST(BudgetErrorModel, TheResolutionTermFollowsTheRowsRendered) {
    EXPECT_EQ(resolution_error(1.0), 0.0);
    EXPECT_LT(resolution_error(2.0), 0.0) << "twice the rows, box-averaged, is closer to the reference";
    EXPECT_DOUBLE_EQ(resolution_error(0.5), error_term(Knob::RenderScale, 0.5));
    // k^2 samples count as k times the rows, where the table's gains end (the larger of twice the
    // rows' and 4 samples' at 2).
    EXPECT_DOUBLE_EQ(resolution_error(2.0),
                     std::min(error_term(Knob::RenderScale, 2.0), error_term(Knob::SamplesPerPixel, 4)));
    EXPECT_DOUBLE_EQ(resolution_error(3.0), error_term(Knob::SamplesPerPixel, 9));
    EXPECT_DOUBLE_EQ(resolution_error(4.0), error_term(Knob::SamplesPerPixel, 16));
    EXPECT_DOUBLE_EQ(resolution_error(8.0), resolution_error(4.0));  // clamped to the table
    const double between = resolution_error(std::sqrt(0.75));        // halfway in log2 from 1 to 0.75
    EXPECT_NEAR(between, 0.5 * error_term(Knob::RenderScale, 0.75), 1e-12);
    const Quality top{1.0, 1024, 256, 64};
    Quality half = top;
    half.render_scale = 0.5;
    EXPECT_DOUBLE_EQ(predict_error(half, top).excess, error_term(Knob::RenderScale, 0.5));
    const double at_600 = predict_error(half, top, 600.0).excess;
    EXPECT_DOUBLE_EQ(at_600, -resolution_error(2.0));
    EXPECT_LT(at_600, predict_error(half, top).excess);
}

// Fewer samples than the command asked for cost what the table says the rows they stand for do;
// the term is named for them when the resolution scale stays.
TEST(BudgetErrorModel, FewerSamplesCostTheRowsTheyStandFor) {
    Quality top{1.0, 1024, 256, 64};
    top.samples = 16;
    Quality four = top;
    four.samples = 4;
    const ErrorPrediction prediction = predict_error(four, top);
    EXPECT_DOUBLE_EQ(prediction.excess, resolution_error(2.0) - resolution_error(4.0));
    EXPECT_GT(prediction.excess, 0.0) << "16 samples measured closer to the box references than 4";
    EXPECT_EQ(prediction.dominant, "samples per pixel");
    // Below full scale the samples count as no more rows: 4 samples at half scale cost what one
    // does there (measured: 4 samples at scale 0.5 or 0.75 sample pool and lake as 1.1-1.3 times
    // the rows, and the frame's cost is 4 times).
    Quality half = four;
    half.render_scale = 0.5;
    EXPECT_DOUBLE_EQ(predict_error(half, top).excess, resolution_error(0.5) - resolution_error(4.0));
    EXPECT_EQ(predict_error(half, top).dominant, "resolution scale");
    Quality half_one_sample = half;
    half_one_sample.samples = 1;
    EXPECT_DOUBLE_EQ(predict_error(half, top).excess, predict_error(half_one_sample, top).excess);
}

// The caustic knobs' terms scale with the scene's caustic visibility: pool's floor 1.5 m down in
// pure water keeps nearly all of them, the ocean's, 30 m down in coastal water, nearly none (the
// sweep measured no excess there at any photon grid); the other terms do not move.
TEST(BudgetErrorModel, TheCausticTermsFollowTheScenesCausticVisibility) {
    const auto scene = [](const char* name) {
        return load_scene(std::filesystem::path(VKWATER_SOURCE_DIR) / "scenes" / name);
    };
    const double pool = caustic_visibility(scene("pool.json")), ocean = caustic_visibility(scene("ocean.json"));
    EXPECT_GT(pool, 0.9);
    EXPECT_LT(pool, 1.0);
    EXPECT_LT(ocean, 1e-3);
    EXPECT_EQ(caustic_visibility(scene("lake.json")), 1.0) << "its post and rock break the surface";
    Quality top{1.0, 1024, 256, 64, 0, false, false, CausticKernel::Adaptive, 1.0};
    Quality lower = top;
    lower.photon_grid = 128;
    lower.mesh_resolution = 128;
    const double mesh = error_term(Knob::MeshResolution, 128);
    top.caustic_visibility = lower.caustic_visibility = ocean;
    EXPECT_NEAR(predict_error(lower, top).excess, mesh + ocean * error_term(Knob::PhotonGridFraction, 0.125), 1e-15);
    EXPECT_EQ(predict_error(lower, top).dominant, "water mesh");
    top.caustic_visibility = lower.caustic_visibility = pool;
    EXPECT_NEAR(predict_error(lower, top).excess, mesh + pool * error_term(Knob::PhotonGridFraction, 0.125), 1e-15);
}

// The kernel's term counts only where the scene's own kernel is not already the bilinear one; the
// map scale's follows the fraction of the scene's.
TEST(BudgetErrorModel, TheCausticKnobsAddTheirTerms) {
    const Quality top{1.0, 1024, 256, 64, 0, false, false, CausticKernel::Adaptive, 1.0};
    Quality bilinear = top;
    bilinear.caustic_kernel = CausticKernel::Bilinear;
    EXPECT_GT(error_term(Knob::BilinearKernel, 1.0), 0.0) << "the measured scenes lose accuracy with it";
    EXPECT_DOUBLE_EQ(predict_error(bilinear, top).excess, error_term(Knob::BilinearKernel, 1.0));
    EXPECT_EQ(predict_error(bilinear, top).dominant, "caustic kernel");
    Quality coarser = bilinear;
    coarser.map_scale = 0.5;
    EXPECT_DOUBLE_EQ(predict_error(coarser, top).excess,
                     error_term(Knob::BilinearKernel, 1.0) + error_term(Knob::MapScaleFraction, 0.5));
    // At a coarser photon grid, the kernel's excess measured there.
    Quality coarse_grid = bilinear;
    coarse_grid.photon_grid = 256;
    EXPECT_DOUBLE_EQ(predict_error(coarse_grid, top).excess,
                     error_term(Knob::PhotonGridFraction, 0.25) + error_term(Knob::BilinearKernel, 0.25));
    Quality own_bilinear = top;
    own_bilinear.caustic_kernel = CausticKernel::Bilinear;
    EXPECT_EQ(predict_error(own_bilinear, own_bilinear).excess, 0.0);
}

// A scene lookup turned off costs what the table measured for it, and the steps' term no longer
// counts once neither lookup runs: lake's ladder (64, 16, 8 steps, then the reflected rays' lookup
// off at 8, then both off) rises in predicted error at every rung.
TEST(BudgetErrorModel, ASceneLookupTurnedOffCostsItsMeasuredExcess) {
    Quality top{1.0, 512, 256, 64};
    top.lookup_steps = 64;
    top.reflection_lookup = top.refraction_lookup = true;
    EXPECT_GT(error_term(Knob::ReflectionLookup, 0.0), 0.0);
    EXPECT_GT(error_term(Knob::RefractionLookup, 0.0), 0.0);
    EXPECT_EQ(error_term(Knob::ReflectionLookup, 1.0), 0.0);
    Quality reflection_off = top;
    reflection_off.reflection_lookup = false;
    EXPECT_DOUBLE_EQ(predict_error(reflection_off, top).excess, error_term(Knob::ReflectionLookup, 0.0));
    EXPECT_EQ(predict_error(reflection_off, top).dominant, "reflection lookup off");
    reflection_off.lookup_steps = 8;
    EXPECT_DOUBLE_EQ(predict_error(reflection_off, top).excess,
                     error_term(Knob::LookupSteps, 8) + error_term(Knob::ReflectionLookup, 0.0));
    Quality both_off = top;
    both_off.lookup_steps = 0;
    both_off.reflection_lookup = both_off.refraction_lookup = false;
    EXPECT_DOUBLE_EQ(predict_error(both_off, top).excess,
                     error_term(Knob::ReflectionLookup, 0.0) + error_term(Knob::RefractionLookup, 0.0));
    EXPECT_EQ(predict_error(both_off, top).dominant,
              error_term(Knob::RefractionLookup, 0.0) > error_term(Knob::ReflectionLookup, 0.0)
                  ? "refraction lookup off"
                  : "reflection lookup off");
    double last = -1.0;
    for (const Quality& rung : {top, Quality{1.0, 512, 256, 64, 16, true, true},
                                Quality{1.0, 512, 256, 64, 8, true, true}, reflection_off, both_off}) {
        const double excess = predict_error(rung, top).excess;
        EXPECT_GT(excess, last) << describe_quality(rung);
        last = excess;
    }
}

// Where the scene's previews measured what an on/off knob loses, that is its term (made a bound as
// the table's are, times kMeasuredTermBound), in place of the table's worst case over the sweep's
// scenes; where they did not (below 0), the table stands.
TEST(BudgetErrorModel, AnOnOffKnobCostsWhatTheScenesPreviewsMeasured) {
    Quality top{1.0, 512, 256, 64};
    top.lookup_steps = 64;
    top.reflection_lookup = top.refraction_lookup = top.second_layer = true;
    top.measured_off = {0.00131, -1.0, 0.00121};  // lake's previews; its refraction left unmeasured
    Quality reflection_off = top;
    reflection_off.reflection_lookup = false;
    EXPECT_DOUBLE_EQ(predict_error(reflection_off, top).excess, kMeasuredTermBound * 0.00131);
    Quality refraction_off = top;
    refraction_off.refraction_lookup = refraction_off.second_layer = false;
    // The layer goes with the refraction lookup, whose loss holds the layer's.
    EXPECT_DOUBLE_EQ(predict_error(refraction_off, top).excess, error_term(Knob::RefractionLookup, 0.0));
    Quality layer_off = top;
    layer_off.second_layer = false;
    EXPECT_DOUBLE_EQ(predict_error(layer_off, top).excess, kMeasuredTermBound * 0.00121);
    EXPECT_EQ(predict_error(layer_off, top).dominant, "refraction second layer");
    top.measured_off.reflection_lookup = 0.0;  // measured: it loses nothing
    reflection_off.measured_off = top.measured_off;
    EXPECT_DOUBLE_EQ(predict_error(reflection_off, top).excess, 0.0);
    EXPECT_EQ(predict_error(reflection_off, top).dominant, "");
}

// Caustics turned off cost what the scene's previews measured, and the caustic knobs' terms no
// longer count: the photon grid, the kernel and the map scale have nothing left to change.
TEST(BudgetErrorModel, TheCausticsOffCostWhatThePreviewsMeasured) {
    Quality top{1.0, 1024, 256, 0};
    top.map_scale = 1.0;
    top.caustics = true;
    top.measured_off.caustics = 2e-7;
    top.measured_off.caustics_largest_change = 0.001;
    Quality off = top;
    off.caustics = false;
    EXPECT_DOUBLE_EQ(predict_error(off, top).excess, kMeasuredTermBound * 2e-7);
    EXPECT_EQ(predict_error(off, top).dominant, "caustics off");
    off.photon_grid = 128;
    EXPECT_DOUBLE_EQ(predict_error(off, top).excess, kMeasuredTermBound * 2e-7)
        << "no photon grid term without caustics";
    Quality fewer = top;
    fewer.photon_grid = 128;
    EXPECT_GT(predict_error(fewer, top).excess, 0.0) << "with them, the photon grid's term";
}

}  // namespace
}  // namespace vkw::budget
