// The budget's candidates: each knob at most the scene's own value, every combination once, and
// the options that name a candidate give the scene that apply_quality makes.
#include "tools/vkwater/budget/quality.hpp"

#include "engine/scene/scene_loader.hpp"
#include "passes/frame/frame_needs.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <set>
#include <sstream>
#include <tuple>

namespace vkw::budget {
namespace {

const std::filesystem::path kPool = std::filesystem::path(VKWATER_SOURCE_DIR) / "scenes/pool.json";
const std::filesystem::path kLake = std::filesystem::path(VKWATER_SOURCE_DIR) / "scenes/lake.json";

TEST(BudgetQuality, CandidatesNeverExceedTheScenesOwnSettings) {
    const Scene scene = load_scene(kPool);
    const Quality top = scene_quality(scene, decide_frame_needs(scene, 4.0 / 3.0));
    EXPECT_EQ(top.photon_grid, 1024u);
    EXPECT_EQ(top.mesh_resolution, 256u);
    EXPECT_EQ(top.godray_grid, 64u);
    EXPECT_EQ(top.lookup_steps, 0u) << "pool's water looks up no scene view";
    EXPECT_EQ(top.caustic_kernel, CausticKernel::Adaptive);
    EXPECT_EQ(top.map_scale, 1.0);
    const std::vector<Quality> candidates = quality_candidates(top);
    // 5 scales x 4 godray settings x (grids 1024, 512, 256 with meshes 256, 128, 64, and grid 128
    // with meshes 128 and 64: its mesh has at most 128 cells) x 2 kernels x 2 map scales, all
    // distinct.
    EXPECT_EQ(candidates.size(), 5u * 4u * (3u * 3u + 2u) * 2u * 2u);
    EXPECT_NE(std::find(candidates.begin(), candidates.end(), top), candidates.end());
    for (const Quality& q : candidates) {
        EXPECT_LE(q.render_scale, top.render_scale);
        EXPECT_LE(q.photon_grid, top.photon_grid);
        EXPECT_LE(q.mesh_resolution, q.photon_grid);
        EXPECT_LE(q.godray_grid, top.godray_grid);
        EXPECT_TRUE(q.caustic_kernel == top.caustic_kernel || q.caustic_kernel == CausticKernel::Bilinear);
        EXPECT_TRUE(q.map_scale == top.map_scale || q.map_scale == 0.5) << q.map_scale;
        EXPECT_EQ(std::count(candidates.begin(), candidates.end(), q), 1);
    }
}

// The refraction view's second layer is a knob where the needs run it (lake), on or off in every
// combination of the other knobs; where they do not (pool), it stays off.
TEST(BudgetQuality, TheSecondLayerTurnsOffOnlyWhereTheNeedsRunIt) {
    const Scene lake = load_scene(kLake);
    const Quality top = scene_quality(lake, decide_frame_needs(lake, 4.0 / 3.0));
    ASSERT_TRUE(top.second_layer);
    std::vector<Quality> candidates = quality_candidates(top);
    // Where the refracted rays still look the scene up (the layer is the refraction view's).
    std::erase_if(candidates, [](const Quality& q) { return !q.refraction_lookup; });
    const auto with_layer =
        std::count_if(candidates.begin(), candidates.end(), [](const Quality& q) { return q.second_layer; });
    EXPECT_GT(with_layer, 0);
    EXPECT_EQ(2 * with_layer, static_cast<std::ptrdiff_t>(candidates.size()));
    for (const Quality& q : candidates) {
        Quality other = q;
        other.second_layer = !q.second_layer;
        EXPECT_NE(std::find(candidates.begin(), candidates.end(), other), candidates.end()) << describe_quality(q);
    }
    Quality off = top;
    off.second_layer = false;
    EXPECT_EQ(describe_arguments(quality_arguments(off, top, lake)), "--set effects.refraction_second_layer.mode=off");
    Scene applied = lake;
    apply_quality(off, top, applied);
    EXPECT_EQ(applied.effects[Effect::RefractionSecondLayer].mode, EffectMode::Off);
    EXPECT_FALSE(scene_quality(applied, decide_frame_needs(applied, 4.0 / 3.0)).second_layer);

    const Scene pool = load_scene(kPool);
    const Quality pool_top = scene_quality(pool, decide_frame_needs(pool, 4.0 / 3.0));
    EXPECT_FALSE(pool_top.second_layer) << "pool's refraction view is not drawn";
    for (const Quality& q : quality_candidates(pool_top)) EXPECT_FALSE(q.second_layer);
}

// Each of a knob's `values` in an equal share of the candidates: every combination of the other
// knobs at each of them.
template <typename Value, size_t N>
void expect_every_combination(const std::vector<Quality>& candidates, Value Quality::*knob, const Value (&values)[N]) {
    for (const Value value : values) {
        const auto count =
            std::count_if(candidates.begin(), candidates.end(), [&](const Quality& q) { return q.*knob == value; });
        EXPECT_EQ(static_cast<std::ptrdiff_t>(N) * count, static_cast<std::ptrdiff_t>(candidates.size())) << value;
    }
}

// The sun shadow map's texels are a knob where receiver meshes cast into it (lake: 1024, 512 and
// 256 in every combination of the other knobs); pool, with no receiver mesh, makes no shadow map.
TEST(BudgetQuality, TheShadowMapTurnsDownOnlyWhereReceiversCastIntoIt) {
    Scene lake = load_scene(kLake);
    const Quality top = scene_quality(lake, decide_frame_needs(lake, 4.0 / 3.0));
    ASSERT_EQ(top.shadow_texels, 1024u);
    const std::vector<Quality> candidates = quality_candidates(top);
    expect_every_combination(candidates, &Quality::shadow_texels, kShadowTexels);
    Quality lower = top;
    lower.shadow_texels = 256;
    EXPECT_EQ(describe_arguments(quality_arguments(lower, top, lake)), "--set sun.shadow_texels=256");
    lake.sun.shadow_texels = 512;  // a scene's own lower map has only the lower steps below it
    const Quality own = scene_quality(lake, decide_frame_needs(lake, 4.0 / 3.0));
    for (const Quality& q : quality_candidates(own)) EXPECT_TRUE(q.shadow_texels == 512 || q.shadow_texels == 256);

    const Scene pool = load_scene(kPool);
    EXPECT_EQ(scene_quality(pool, decide_frame_needs(pool, 4.0 / 3.0)).shadow_texels, 0u);
}

// The terrain's cells are a knob where the scene has a terrain receiver (lake's bed: its own 128,
// 64 and 32 in every combination of the other knobs), set per receiver in the options and quoted
// for a shell; applying a setting rebuilds only the terrain, and the top rebuilds it back.
TEST(BudgetQuality, TheTerrainTurnsDownOnlyWhereTheSceneHasOne) {
    const Scene lake = load_scene(kLake);
    const Quality top = scene_quality(lake, decide_frame_needs(lake, 4.0 / 3.0));
    ASSERT_EQ(top.terrain_fraction, 1.0);
    ASSERT_EQ(lake.receivers[0].terrain->resolution, 128u);
    const std::vector<Quality> candidates = quality_candidates(top);
    expect_every_combination(candidates, &Quality::terrain_fraction, kTerrainFractions);
    Quality lower = top;
    lower.terrain_fraction = 0.25;
    EXPECT_EQ(quality_arguments(lower, top, lake), std::vector<std::string>{"--set receivers[0].resolution=32"});
    EXPECT_EQ(describe_arguments(quality_arguments(lower, top, lake)), "--set 'receivers[0].resolution=32'");
    Scene applied = lake;
    apply_quality(lower, top, applied);
    EXPECT_EQ(applied.receivers[0].mesh.positions.size(), 33u * 33u);
    EXPECT_EQ(applied.receivers[0].mesh.indices.size(), 6u * 32u * 32u);
    for (size_t i = 1; i < lake.receivers.size(); ++i) {
        EXPECT_EQ(applied.receivers[i].mesh.positions, lake.receivers[i].mesh.positions) << i;
    }
    apply_quality(top, top, applied);
    EXPECT_EQ(applied.receivers[0].mesh.positions, lake.receivers[0].mesh.positions);
    EXPECT_EQ(applied.receivers[0].mesh.normals, lake.receivers[0].mesh.normals);

    const Scene pool = load_scene(kPool);
    const Quality pool_top = scene_quality(pool, decide_frame_needs(pool, 4.0 / 3.0));
    EXPECT_EQ(pool_top.terrain_fraction, 0.0);
    for (const Quality& q : quality_candidates(pool_top)) EXPECT_EQ(q.terrain_fraction, 0.0);
}

// The scene lookups' ladder where the water looks the scene up (lake, seen from above): the steps
// 64, 16 and 8, each with both lookups and with the reflected rays' lookup off, then both off, each
// rung in every combination of the other knobs; with a lookup off its view's second layer is off too.
// Pool looks nothing up and has no rung.
TEST(BudgetQuality, TheSceneLookupsTurnOffOneAtEachStepsThenBoth) {
    const Scene lake = load_scene(kLake);
    const Quality top = scene_quality(lake, decide_frame_needs(lake, 4.0 / 3.0));
    ASSERT_TRUE(top.reflection_lookup && top.refraction_lookup);
    const std::vector<Quality> candidates = quality_candidates(top);
    std::set<std::tuple<uint32_t, bool, bool>> rungs;
    for (const Quality& q : candidates) {
        rungs.insert({q.lookup_steps, q.reflection_lookup, q.refraction_lookup});
        if (!q.refraction_lookup) {
            EXPECT_FALSE(q.second_layer) << describe_quality(q);
        }
    }
    const std::set<std::tuple<uint32_t, bool, bool>> ladder = {{64, true, true},  {64, false, true}, {16, true, true},
                                                               {16, false, true}, {8, true, true},   {8, false, true},
                                                               {0, false, false}};
    EXPECT_EQ(rungs, ladder);
    const auto at_rung = [&](uint32_t steps, bool reflection, bool refraction) {
        return std::count_if(candidates.begin(), candidates.end(), [&](const Quality& q) {
            return q.lookup_steps == steps && q.reflection_lookup == reflection && q.refraction_lookup == refraction;
        });
    };
    // With both lookups off there is no second layer to turn: half as many candidates at that rung.
    const std::ptrdiff_t each = at_rung(64, true, true), none = at_rung(0, false, false);
    for (uint32_t steps : {64u, 16u, 8u}) EXPECT_EQ(at_rung(steps, false, true), each) << steps;
    EXPECT_EQ(2 * none, each);
    EXPECT_EQ(static_cast<std::ptrdiff_t>(candidates.size()), 6 * each + none);

    Quality reflection_off = top;
    reflection_off.lookup_steps = 8;
    reflection_off.reflection_lookup = false;
    EXPECT_EQ(describe_arguments(quality_arguments(reflection_off, top, lake)),
              "--set effects.reflection.max_steps=8 --set effects.refraction.max_steps=8 --set "
              "effects.reflection.mode=off");
    Quality both_off = reflection_off;
    both_off.lookup_steps = 0;
    both_off.refraction_lookup = false;
    both_off.second_layer = false;
    EXPECT_EQ(describe_arguments(quality_arguments(both_off, top, lake)),
              "--set effects.reflection.mode=off --set effects.refraction.mode=off "
              "--set effects.refraction_second_layer.mode=off");
    Scene applied = lake;
    apply_quality(both_off, top, applied);
    const fg::FrameNeeds needs = decide_frame_needs(applied, 4.0 / 3.0);
    EXPECT_FALSE(needs.find(Effect::Reflection)->needed);
    EXPECT_FALSE(needs.find(Effect::Refraction)->needed);

    // Seen from under the water (the lagoon) the refracted rays' lookup goes first.
    const Scene lagoon = load_scene(std::filesystem::path(VKWATER_SOURCE_DIR) / "scenes/showcase/lagoon.json");
    const Quality lagoon_top = scene_quality(lagoon, decide_frame_needs(lagoon, 4.0 / 3.0));
    ASSERT_TRUE(lagoon_top.camera_in_water && lagoon_top.reflection_lookup && lagoon_top.refraction_lookup);
    for (const Quality& q : quality_candidates(lagoon_top)) {
        EXPECT_FALSE(!q.reflection_lookup && q.refraction_lookup) << describe_quality(q);
    }

    const Scene pool = load_scene(kPool);
    const Quality pool_top = scene_quality(pool, decide_frame_needs(pool, 4.0 / 3.0));
    EXPECT_EQ(pool_top.scene_lookups(), 0u);
    for (const Quality& q : quality_candidates(pool_top)) EXPECT_EQ(q.scene_lookups(), 0u);
}

// Where the scene's previews measured both lookups, the one whose loss they measured as the smaller
// goes first, whichever side the camera is on: box, seen from above, loses 0.138 without its
// reflected rays' lookup (its red box in the water) and 0.0088 without its refracted rays'
// (docs/performance-log.md "The on/off knobs measured on the scene"), so its refracted rays' lookup goes first. Equal
// losses, or one not measured, leave the camera's rule.
TEST(BudgetQuality, TheSceneLookupWhosePreviewsLostLessGoesFirst) {
    const Scene box = load_scene(std::filesystem::path(VKWATER_SOURCE_DIR) / "scenes/box.json");
    Quality top = scene_quality(box, decide_frame_needs(box, 4.0 / 3.0));
    ASSERT_TRUE(top.reflection_lookup && top.refraction_lookup && !top.camera_in_water);
    const auto single_off_rungs = [&] {
        std::set<std::pair<bool, bool>> rungs;
        for (const Quality& q : quality_candidates(top)) {
            if (q.scene_lookups() == 1) rungs.insert({q.reflection_lookup, q.refraction_lookup});
        }
        return rungs;
    };
    const std::set<std::pair<bool, bool>> reflection_kept = {{true, false}}, refraction_kept = {{false, true}};
    EXPECT_EQ(single_off_rungs(), refraction_kept) << "unmeasured: the camera's rule";
    top.measured_off.reflection_lookup = 0.138;
    top.measured_off.refraction_lookup = 0.0088;
    EXPECT_EQ(single_off_rungs(), reflection_kept);
    top.measured_off.refraction_lookup = 0.138;
    EXPECT_EQ(single_off_rungs(), refraction_kept) << "equal losses: the camera's rule";
    top.measured_off.refraction_lookup = -1.0;
    EXPECT_EQ(single_off_rungs(), refraction_kept) << "one unmeasured: the camera's rule";
    top.measured_off = {0.0003, 0.0, 0.0};  // the lagoon's order, measured, from above
    EXPECT_EQ(single_off_rungs(), reflection_kept);
}

// The caustics off are a candidate only where the previews found that no pixel changes visibly
// without them (at most kGodraysInvisibleChange of its value): then every candidate has a twin
// without them, with the top's kernel and map scale, and an unmeasured or visible change offers none.
TEST(BudgetQuality, TheCausticsTurnOffOnlyWhereThePreviewsSawNoChange) {
    const Scene ocean = load_scene(std::filesystem::path(VKWATER_SOURCE_DIR) / "scenes/ocean.json");
    Quality top = scene_quality(ocean, decide_frame_needs(ocean, 4.0 / 3.0));
    ASSERT_TRUE(top.caustics);
    const auto count_off = [&] {
        const std::vector<Quality> candidates = quality_candidates(top);
        const auto off = std::count_if(candidates.begin(), candidates.end(), [&](const Quality& q) {
            EXPECT_TRUE(q.caustics || (q.caustic_kernel == top.caustic_kernel && q.map_scale == top.map_scale));
            return !q.caustics;
        });
        return std::pair<std::ptrdiff_t, size_t>{off, candidates.size()};
    };
    const size_t on_only = count_off().second;
    EXPECT_EQ(count_off().first, 0) << "unmeasured";
    top.measured_off.caustics = 0.0;
    top.measured_off.caustics_largest_change = 0.99 * kGodraysInvisibleChange;
    const auto [off, all] = count_off();
    EXPECT_GT(off, 0);
    // Every combination of the knobs but the kernel and the map scale, once more.
    const size_t kernels_and_scales = 2 * 2;
    EXPECT_EQ(all, on_only + on_only / kernels_and_scales);
    top.measured_off.caustics_largest_change = 1.01 * kGodraysInvisibleChange;
    EXPECT_EQ(count_off().first, 0) << "a visible change";
    Quality off_setting = top;
    off_setting.caustics = false;
    EXPECT_EQ(describe_arguments(quality_arguments(off_setting, top, ocean)), "--set effects.caustics.mode=off");
    Scene applied = ocean;
    apply_quality(off_setting, top, applied);
    EXPECT_FALSE(decide_frame_needs(applied, 4.0 / 3.0).needs(Effect::SurfaceCaustics));
}

// The viewer applies each frame's setting to the scene it applied the last one to: with the scene's
// own fields put back first, any setting followed by the top gives the scene as loaded (lake:
// its mesh, second layer, shadow map, lookups and terrain all back).
TEST(BudgetQuality, TheTopAfterALowerSettingGivesTheSceneBack) {
    const Scene original = load_scene(kLake);
    const Quality top = scene_quality(original, decide_frame_needs(original, 4.0 / 3.0));
    const SceneKnobFields at_load = knob_fields(original);
    const std::vector<Quality> candidates = quality_candidates(top);
    const Quality& cheapest = candidates.back();  // every knob at its lowest step
    ASSERT_LT(cheapest.mesh_resolution, top.mesh_resolution);
    ASSERT_FALSE(cheapest.second_layer || cheapest.reflection_lookup || cheapest.refraction_lookup);
    Scene scene = original;
    for (const Quality& q : {cheapest, top}) {
        restore_knob_fields(at_load, scene);
        apply_quality(q, top, scene);
    }
    EXPECT_EQ(scene.water->drawn_mesh_resolution(), original.water->drawn_mesh_resolution());
    EXPECT_EQ(scene.water->grid_resolution, original.water->grid_resolution);
    for (Effect effect :
         {Effect::VolumeCaustics, Effect::Reflection, Effect::Refraction, Effect::RefractionSecondLayer}) {
        EXPECT_EQ(scene.effects[effect].mode, original.effects[effect].mode) << effect_name(effect);
        EXPECT_EQ(scene.effects[effect].max_steps, original.effects[effect].max_steps) << effect_name(effect);
    }
    EXPECT_EQ(scene.effects.godrays.grid, original.effects.godrays.grid);
    EXPECT_EQ(scene.effects.caustics.kernel, original.effects.caustics.kernel);
    EXPECT_EQ(scene.effects.caustics.map_scale, original.effects.caustics.map_scale);
    EXPECT_EQ(scene.sun.shadow_texels, original.sun.shadow_texels);
    EXPECT_EQ(scene.receivers[0].mesh.positions, original.receivers[0].mesh.positions);
    EXPECT_EQ(scene_quality(scene, decide_frame_needs(scene, 4.0 / 3.0)), top);
}

// The kernel and the map's scale are knobs only where photons are splatted into the light-space
// map: a scene already on the bilinear kernel keeps it, and at the lowest map scale there is no
// lower one; the camera-space splats have neither knob.
TEST(BudgetQuality, TheCausticKnobsTurnOnlyWhatTheSceneHas) {
    Scene scene = load_scene(kPool);
    scene.effects.caustics.kernel = CausticKernel::Bilinear;
    scene.effects.caustics.map_scale = kMinMapScale;
    Quality top = scene_quality(scene, decide_frame_needs(scene, 4.0 / 3.0));
    for (const Quality& q : quality_candidates(top)) {
        EXPECT_EQ(q.caustic_kernel, CausticKernel::Bilinear);
        EXPECT_EQ(q.map_scale, kMinMapScale);
    }
    scene.effects.caustics.splat = CausticSplat::CameraSpace;
    top = scene_quality(scene, decide_frame_needs(scene, 4.0 / 3.0));
    EXPECT_EQ(top.map_scale, 0.0);
    EXPECT_EQ(quality_candidates(top).size(), 5u * 4u * (3u * 3u + 2u));
}

// The samples per pixel are the command's (--spp N), not the scene's: the candidates take every
// square up to N, each with every other knob's combinations, and the options name them whenever
// they are above one.
TEST(BudgetQuality, TheSamplesAreSquaresUpToTheCommands) {
    const Scene scene = load_scene(kPool);
    const fg::FrameNeeds needs = decide_frame_needs(scene, 4.0 / 3.0);
    const Quality one = scene_quality(scene, needs);
    EXPECT_EQ(one.samples, 1u);
    const Quality nine = scene_quality(scene, needs, 9);
    const std::vector<Quality> candidates = quality_candidates(nine);
    EXPECT_EQ(candidates.size(), 3u * quality_candidates(one).size());
    std::set<uint32_t> samples;
    for (const Quality& q : candidates) samples.insert(q.samples);
    EXPECT_EQ(samples, (std::set<uint32_t>{1, 4, 9}));
    EXPECT_TRUE(quality_arguments(one, one, scene).empty());
    EXPECT_EQ(describe_arguments(quality_arguments(nine, nine, scene)), "--spp 9");
    Quality four = nine;
    four.samples = 4;
    four.render_scale = 0.5;
    EXPECT_EQ(describe_arguments(quality_arguments(four, nine, scene)), "--render-scale 0.5 --spp 4");
}

TEST(BudgetQuality, ASceneWithoutWaterTurnsOnlyTheResolution) {
    Scene scene = load_scene(kPool);
    scene.water.reset();
    const Quality top = scene_quality(scene, decide_frame_needs(scene, 4.0 / 3.0));
    EXPECT_EQ(quality_candidates(top).size(), std::size(kRenderScales));
}

// Infinite water (ocean) has no uniform mesh to turn: every candidate keeps the screen's grid, and
// its options, given back, load (a uniform mesh would be refused there).
TEST(BudgetQuality, InfiniteWaterKeepsTheScreensGrid) {
    const Scene original = load_scene(std::filesystem::path(VKWATER_SOURCE_DIR) / "scenes/ocean.json");
    ASSERT_TRUE(original.water->infinite);
    const Quality top = scene_quality(original, decide_frame_needs(original, 4.0 / 3.0));
    EXPECT_EQ(top.mesh_resolution, 0u);
    for (const Quality& q : quality_candidates(top)) {
        EXPECT_EQ(q.mesh_resolution, 0u);
        Scene applied = original;
        apply_quality(q, top, applied);
        EXPECT_FALSE(applied.water->mesh_resolution.has_value());
        EXPECT_EQ(applied.water->screen_mesh_cell_pixels(), original.water->screen_mesh_cell_pixels());
        for (const std::string& argument : quality_arguments(q, top, original)) {
            EXPECT_EQ(argument.find("mesh_resolution"), std::string::npos) << argument;
        }
    }
}

// The options a budgeted render prints, given back as --set and --render-scale, make the same scene
// (lake: it has every knob, the scene lookups' steps too).
TEST(BudgetQuality, ItsOptionsGiveTheSceneApplyQualityMakes) {
    const Scene original = load_scene(kLake);
    const Quality top = scene_quality(original, decide_frame_needs(original, 4.0 / 3.0));
    ASSERT_EQ(top.scene_lookups(), 2u) << "lake looks up both scene views";
    ASSERT_EQ(top.lookup_steps, 64u);
    ASSERT_EQ(top.godray_grid, 64u);
    ASSERT_GT(top.map_scale, 0.0) << "lake splats photons into the light-space map";
    const double half_map = std::max(kMinMapScale, 0.5 * top.map_scale);
    ASSERT_TRUE(top.second_layer) << "lake's refraction view has a second layer";
    ASSERT_EQ(top.shadow_texels, 1024u) << "lake's receivers cast into the sun shadow map";
    ASSERT_EQ(top.terrain_fraction, 1.0) << "lake's bed is a terrain";
    // The first two turn the second layer off, the third keeps it; each has its own shadow map and
    // its own terrain detail; the next two turn the reflected rays' lookup off, then both, and the
    // last before the top the caustics too.
    for (const Quality& q :
         {Quality{0.5, 128, 128, 0, 8, true, true, CausticKernel::Bilinear, half_map, 1, false, 256, 0.25, true},
          Quality{1.0, 256, 256, 32, 64, true, true, top.caustic_kernel, half_map, 1, false, 1024, 1.0, true},
          Quality{0.35, 64, 64, 16, 16, true, true, CausticKernel::Bilinear, top.map_scale, 1, true, 512, 0.5, true},
          Quality{0.25, 64, 64, 0, 8, false, true, CausticKernel::Bilinear, half_map, 1, false, 256, 0.25, true},
          Quality{0.25, 64, 64, 0, 0, false, false, CausticKernel::Bilinear, half_map, 1, false, 256, 0.25, true},
          Quality{0.25, 64, 64, 0, 0, false, false, top.caustic_kernel, top.map_scale, 1, false, 256, 0.25, false},
          top}) {
        Scene applied = original;
        apply_quality(q, top, applied);
        std::vector<std::string> overrides;
        double scale = 1.0;
        for (const std::string& argument : quality_arguments(q, top, original)) {
            std::istringstream words(argument);
            std::string option, value;
            words >> option >> value;
            if (option == "--set") overrides.push_back(value);
            if (option == "--render-scale") scale = std::stod(value);
        }
        const Scene given = load_scene(kLake, overrides);
        EXPECT_EQ(scale, q.render_scale);
        EXPECT_EQ(given.water->grid_resolution, applied.water->grid_resolution);
        EXPECT_EQ(given.water->drawn_mesh_resolution(), applied.water->drawn_mesh_resolution());
        EXPECT_EQ(given.effects[Effect::VolumeCaustics].mode, applied.effects[Effect::VolumeCaustics].mode);
        EXPECT_EQ(given.effects.godrays.grid, applied.effects.godrays.grid);
        EXPECT_EQ(given.effects[Effect::Reflection].max_steps, applied.effects[Effect::Reflection].max_steps);
        EXPECT_EQ(given.effects[Effect::Refraction].max_steps, applied.effects[Effect::Refraction].max_steps);
        EXPECT_EQ(given.effects[Effect::Reflection].mode, applied.effects[Effect::Reflection].mode);
        EXPECT_EQ(given.effects[Effect::Refraction].mode, applied.effects[Effect::Refraction].mode);
        EXPECT_EQ(given.effects[Effect::SurfaceCaustics].mode, applied.effects[Effect::SurfaceCaustics].mode);
        EXPECT_EQ(given.effects.caustics.kernel, applied.effects.caustics.kernel);
        EXPECT_EQ(given.effects.caustics.map_scale, applied.effects.caustics.map_scale);
        EXPECT_EQ(given.effects[Effect::RefractionSecondLayer].mode,
                  applied.effects[Effect::RefractionSecondLayer].mode);
        EXPECT_EQ(given.sun.shadow_texels, applied.sun.shadow_texels);
        ASSERT_EQ(given.receivers.size(), applied.receivers.size());
        for (size_t i = 0; i < given.receivers.size(); ++i) {
            EXPECT_EQ(given.receivers[i].mesh.positions, applied.receivers[i].mesh.positions) << i;
            EXPECT_EQ(given.receivers[i].mesh.indices, applied.receivers[i].mesh.indices) << i;
        }
        Quality in_the_scene = q;  // the resolution scale is the renderer's option, not the scene's
        in_the_scene.render_scale = 1.0;
        in_the_scene.terrain_fraction = 1.0;  // the given terrain's own cells are the lowered ones
        if (!q.caustics) {                    // without caustics the scene has no photon map to turn
            in_the_scene.map_scale = 0.0;
            in_the_scene.caustic_kernel = CausticKernel::Adaptive;
        }
        EXPECT_EQ(scene_quality(given, decide_frame_needs(given, 4.0 / 3.0)), in_the_scene);
    }
    EXPECT_EQ(describe_arguments(quality_arguments(top, top, original)), "the scene's own settings");
}

}  // namespace
}  // namespace vkw::budget
