// The scene's needs (passes/frame/frame_needs.cpp), one test per rule, without a
// GPU: the water is needed when its box is in view, the underwater path when the
// near plane can reach into the water; effects.<name>.mode forces either way and is
// marked forced; every decision carries its reason.
#include "passes/frame/frame_needs.hpp"
#include "engine/scene/scene_loader.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <string>
#include <vector>

namespace vkw {
namespace {

Scene scene_with(const std::string& camera, const std::vector<std::string>& overrides = {}) {
    return parse_scene(R"({
      "camera": {)" + camera +
                           R"(, "fov_y_deg": 60, "near": 0.05},
      "sun": {"elevation_deg": 60},
      "sky": {"radiance": [1, 1, 1]},
      "floor": {"height": -2, "half_extent": 10},
      "water": {"level": 0, "half_extent": 10,
                "waves": {"model": "sum", "components": [{"amplitude": 0.1, "wavelength": 2}]}}
    })",
                       "needs_test.json", overrides);
}

const fg::EffectDecision& decision(const fg::FrameNeeds& needs, Effect effect) {
    const fg::EffectDecision* found = needs.find(effect);
    EXPECT_NE(found, nullptr);
    return *found;
}

TEST(frame_needs, WaterNeededOnlyWhenItsBoxIsInView) {
    const auto looking_at = decide_frame_needs(scene_with(R"("position": [0, 2, 5], "target": [0, 0, 0])"), 4.0 / 3.0);
    EXPECT_TRUE(decision(looking_at, Effect::Water).needed);
    const auto looking_away =
        decide_frame_needs(scene_with(R"("position": [0, 2, 50], "target": [0, 2, 100])"), 4.0 / 3.0);
    EXPECT_FALSE(decision(looking_away, Effect::Water).needed);
    EXPECT_NE(decision(looking_away, Effect::Water).reason.find("outside the view"), std::string::npos);
}

TEST(frame_needs, UnderwaterViewFollowsTheNearPlaneAgainstTheCrests) {
    // Crests reach 0.1 m: a camera at 1 m does not need the underwater path, one at 0.1 m,
    // on the plane, or below does (the near plane is 0.05 m away).
    for (const auto& [height, needed] : std::vector<std::pair<double, bool>>{
             {1.0, false}, {0.2, false}, {0.1, true}, {0.0, true}, {-1e-6, true}, {-1.0, true}}) {
        const std::string camera =
            "\"position\": [0, " + std::to_string(height) + ", 0], \"target\": [0, " + std::to_string(height) + ", -1]";
        const auto needs = decide_frame_needs(scene_with(camera), 4.0 / 3.0);
        EXPECT_EQ(decision(needs, Effect::UnderwaterView).needed, needed) << "camera at y = " << height;
        EXPECT_FALSE(decision(needs, Effect::UnderwaterView).reason.empty());
    }
}

TEST(frame_needs, ModesForceTheDecisionAndSaySo) {
    const std::string camera = R"("position": [0, 2, 5], "target": [0, 0, 0])";
    const auto off = decide_frame_needs(scene_with(camera, {"effects.water.mode=off"}), 1.0);
    EXPECT_FALSE(decision(off, Effect::Water).needed);
    EXPECT_TRUE(decision(off, Effect::Water).forced);
    const auto on = decide_frame_needs(scene_with(camera, {"effects.underwater_view.mode=on"}), 1.0);
    EXPECT_TRUE(decision(on, Effect::UnderwaterView).needed);
    EXPECT_TRUE(decision(on, Effect::UnderwaterView).forced);
    EXPECT_NE(decision(on, Effect::UnderwaterView).reason.find("mode = on"), std::string::npos);
    const auto automatic = decide_frame_needs(scene_with(camera), 1.0);
    EXPECT_FALSE(decision(automatic, Effect::Water).forced);
}

TEST(frame_needs, CausticsNeedTheSunUpAndTheFloorUnderTheWater) {
    const std::string camera = R"("position": [0, 2, 5], "target": [0, 0, 0])";
    EXPECT_TRUE(decision(decide_frame_needs(scene_with(camera), 1.0), Effect::SurfaceCaustics).needed);
    const auto night = decide_frame_needs(scene_with(camera, {"sun.elevation_deg=-1"}), 1.0);
    EXPECT_FALSE(decision(night, Effect::SurfaceCaustics).needed);
    EXPECT_NE(decision(night, Effect::SurfaceCaustics).reason.find("below the horizon"), std::string::npos);
    // A floor above the highest crest (the water given its own bottom by water.depth).
    const auto dry = decide_frame_needs(scene_with(camera, {"floor.height=0.5", "water.depth=1"}), 1.0);
    EXPECT_FALSE(decision(dry, Effect::SurfaceCaustics).needed);
}

TEST(frame_needs, NoWaterNoWaterEffects) {
    const auto needs =
        decide_frame_needs(scene_with(R"("position": [0, 2, 5], "target": [0, 0, 0])", {"water=null"}), 1.0);
    EXPECT_FALSE(decision(needs, Effect::Water).needed);
    EXPECT_FALSE(decision(needs, Effect::UnderwaterView).needed);
}

TEST(frame_needs, TheSecondLayerOfTheRefractionViewWhereOneReceiverCanHideAnother) {
    const std::string camera = R"("position": [0, 2, 5], "target": [0, 0, 0])";
    const std::string sphere = R"({"type": "sphere", "radius": 0.3, "translation": [0, -1, 0]})";
    const std::string box = R"({"type": "box", "half_size": [0.3, 0.3, 0.3], "translation": [1, -1, 0]})";
    const std::string terrain = R"({"type": "terrain", "size": 4, "resolution": 8, "height": 0.5, "seed": 1,
                                    "translation": [0, -1.5, 0]})";
    const auto second_layer = [&](const std::string& receivers) {
        return decision(decide_frame_needs(scene_with(camera, {"receivers=[" + receivers + "]"}), 1.0),
                        Effect::RefractionSecondLayer);
    };
    const fg::EffectDecision alone = second_layer(sphere);
    EXPECT_FALSE(alone.needed);
    EXPECT_NE(alone.reason.find("only its own back"), std::string::npos) << alone.reason;
    const fg::EffectDecision two = second_layer(sphere + ", " + box);
    EXPECT_TRUE(two.needed);
    EXPECT_NE(two.reason.find("2 receiver meshes"), std::string::npos) << two.reason;
    const fg::EffectDecision hills = second_layer(terrain);
    EXPECT_TRUE(hills.needed);
    EXPECT_NE(hills.reason.find("not convex"), std::string::npos) << hills.reason;
    // Both above the water, the camera above: no refraction view to peel.
    const fg::EffectDecision dry = second_layer(
        R"({"type": "sphere", "radius": 0.3, "translation": [0, 1, 0]}, {"type": "sphere", "radius": 0.3, "translation": [1, 1, 0]})");
    EXPECT_FALSE(dry.needed);
    EXPECT_NE(dry.reason.find("not drawn"), std::string::npos) << dry.reason;
}

TEST(frame_needs, DecidedIntoTheLastFramesNeedsTheyEqualAFreshDecision) {
    // The renderer decides each frame's needs into the strings of the last frame's reasons
    // (fg::FrameNeeds::clear). Whatever the last frame decided, the new decisions, their order and
    // their reasons must be a fresh decision's: every built-in scene after every other, with a
    // mode forced and without.
    const std::filesystem::path scenes = std::filesystem::path(VKWATER_SOURCE_DIR) / "scenes";
    std::vector<Scene> all;
    for (const char* name : {"pool.json", "lake.json", "ocean.json", "box.json", "calm.json", "underwater.json",
                             "showcase/shore.json", "showcase/lagoon.json"}) {
        all.push_back(load_scene(scenes / name));
        all.push_back(load_scene(scenes / name, {"effects.reflection.mode=on", "effects.godrays.mode=off"}));
    }
    all.push_back(scene_with(R"("position": [0, 2, 5], "target": [0, 0, 0])", {"water=null"}));
    for (const Scene& last : all) {
        for (const Scene& next : all) {
            fg::FrameNeeds needs = decide_frame_needs(last, 4.0 / 3.0);
            decide_frame_needs(next, 4.0 / 3.0, needs);
            EXPECT_EQ(needs.describe(), decide_frame_needs(next, 4.0 / 3.0).describe())
                << next.source << " decided after " << last.source;
        }
    }
}

TEST(frame_needs, WaterBoundsHoldTheCrestsAndTheBottom) {
    const WaterBounds bounds = water_bounds(scene_with(R"("position": [0, 2, 5], "target": [0, 0, 0])"));
    EXPECT_DOUBLE_EQ(bounds.hi.y, 0.1);
    EXPECT_DOUBLE_EQ(bounds.lo.y, -2.0);
}

}  // namespace
}  // namespace vkw
