// The godrays' needs rule (passes/frame/frame_needs.cpp), one test per reason, and their scene
// fields (effects.godrays in scenes/README.md): defaults, every field read, each out-of-range value
// refused naming the field and the accepted range. No GPU.
#include "engine/scene/scene_loader.hpp"
#include "passes/frame/frame_needs.hpp"
#include "passes/godrays/godrays.hpp"

#include <gtest/gtest.h>

#include <string>
#include <vector>

namespace vkw {
namespace {

// Wavy water (so that the flat-water reason stays out of the way) with a scattering medium, the
// camera above it looking at it, the sun up.
Scene scene_with(const std::vector<std::string>& overrides = {}) {
    return parse_scene(R"({
      "camera": {"position": [0, 2, 5], "target": [0, 0, 0]},
      "sun": {"elevation_deg": 60},
      "sky": {"radiance": [1, 1, 1]},
      "floor": {"height": -2, "half_extent": 10},
      "water": {"level": 0, "half_extent": 10,
                "waves": {"model": "sum", "components": [{"amplitude": 0.1, "wavelength": 2}]}},
      "medium": {"preset": "coastal"}
    })",
                       "godrays_needs_test.json", overrides);
}

// A copy: the needs it comes from are often a temporary.
fg::EffectDecision godrays(const fg::FrameNeeds& needs) {
    const fg::EffectDecision* found = needs.find(Effect::VolumeCaustics);
    EXPECT_NE(found, nullptr);
    return found ? *found : fg::EffectDecision{Effect::VolumeCaustics};
}

fg::FrameNeeds needs_of(const std::vector<std::string>& overrides) {
    return decide_frame_needs(scene_with(overrides), 1.0);
}

bool says(const fg::EffectDecision& decision, const std::string& text) {
    return decision.reason.find(text) != std::string::npos;
}

TEST(godrays_needs, NeededWhenTheLitScatteringWaterIsInView) {
    const auto decision = godrays(needs_of({}));
    EXPECT_TRUE(decision.needed);
    EXPECT_FALSE(decision.forced);
    EXPECT_TRUE(says(decision, "scatters")) << decision.reason;
}

TEST(godrays_needs, CulledWithoutScattering) {
    const auto decision =
        godrays(needs_of({"medium.preset=null", "medium.sigma_a=[0.5, 0.1, 0.05]", "medium.sigma_s=[0, 0, 0]"}));
    EXPECT_FALSE(decision.needed);
    EXPECT_TRUE(says(decision, "sigma_s = 0")) << decision.reason;
    // One scattering channel is enough.
    EXPECT_TRUE(
        godrays(needs_of({"medium.preset=null", "medium.sigma_a=[0.5, 0.1, 0.05]", "medium.sigma_s=[0, 0, 1e-6]"}))
            .needed);
}

TEST(godrays_needs, CulledWithTheSunDown) {
    const auto decision = godrays(needs_of({"sun.elevation_deg=-1"}));
    EXPECT_FALSE(decision.needed);
    EXPECT_TRUE(says(decision, "below the horizon")) << decision.reason;
}

TEST(godrays_needs, CulledWithoutWaterInView) {
    const auto away = godrays(needs_of({"camera.position=[0, 2, 50]", "camera.target=[0, 2, 100]"}));
    EXPECT_FALSE(away.needed);
    EXPECT_TRUE(says(away, "not in view")) << away.reason;
    const auto dry = godrays(needs_of({"water=null"}));
    EXPECT_FALSE(dry.needed);
    EXPECT_TRUE(says(dry, "no water")) << dry.reason;
}

TEST(godrays_needs, CulledUnderFlatWaterWithNothingOverIt) {
    // Uniform beams: the shading's analytic in-scatter is exact there.
    const auto flat = godrays(needs_of({"water.waves=null"}));
    EXPECT_FALSE(flat.needed);
    EXPECT_TRUE(says(flat, "flat")) << flat.reason;
    // An object over the flat water shades some beams: needed again.
    const auto shaded =
        godrays(needs_of({"water.waves=null",
                          R"(receivers=[{"type": "box", "half_size": [0.5, 0.5, 0.5], "translation": [0, 1, 0]}])"}));
    EXPECT_TRUE(shaded.needed) << shaded.reason;
}

TEST(godrays_needs, ModesForceEitherWay) {
    const auto on = godrays(needs_of({"sun.elevation_deg=-1", "effects.godrays.mode=on"}));
    EXPECT_TRUE(on.needed);
    EXPECT_TRUE(on.forced);
    EXPECT_TRUE(says(on, "mode = on")) << on.reason;
    const auto off = godrays(needs_of({"effects.godrays.mode=off"}));
    EXPECT_FALSE(off.needed);
    EXPECT_TRUE(off.forced);
}

TEST(godrays_scene, DefaultsAndEveryField) {
    const GodraySettings defaults = scene_with().effects.godrays;
    EXPECT_EQ(defaults.grid, 64u);
    EXPECT_EQ(defaults.resolution_scale, 1.0);
    EXPECT_FALSE(defaults.max_depth.has_value());
    EXPECT_EQ(defaults.method, GodrayMethod::Lines);
    EXPECT_EQ(defaults.march_steps, 32u);
    const GodraySettings set =
        scene_with({"effects.godrays.grid=256", "effects.godrays.resolution_scale=0.5", "effects.godrays.max_depth=7.5",
                    "effects.godrays.method=marched", "effects.godrays.march_steps=9", "effects.godrays.mode=on"})
            .effects.godrays;
    EXPECT_EQ(set.grid, 256u);
    EXPECT_EQ(set.resolution_scale, 0.5);
    EXPECT_EQ(set.max_depth, 7.5);
    EXPECT_EQ(set.method, GodrayMethod::Marched);
    EXPECT_EQ(set.march_steps, 9u);
}

std::string error_of(const std::string& override_text) {
    try {
        scene_with({override_text});
    } catch (const UserError& error) {
        return error.what();
    }
    ADD_FAILURE() << override_text << " was accepted";
    return {};
}

TEST(godrays_scene, OutOfRangeFieldsAreRefusedNamingFieldAndRange) {
    const std::vector<std::pair<std::string, std::vector<std::string>>> cases = {
        {"effects.godrays.grid=1", {"effects.godrays.grid: 1 is out of range", "2 <= value <= 1024"}},
        {"effects.godrays.grid=2048", {"effects.godrays.grid: 2048 is out of range"}},
        {"effects.godrays.grid=64.5", {"effects.godrays.grid"}},
        {"effects.godrays.resolution_scale=0.75", {"effects.godrays.resolution_scale: 0.75", "0.5 or 1"}},
        {"effects.godrays.resolution_scale=2", {"effects.godrays.resolution_scale: 2 is out of range"}},
        {"effects.godrays.max_depth=0", {"effects.godrays.max_depth: 0 is out of range", "value > 0 m"}},
        {"effects.godrays.method=rays", {"effects.godrays.method", "lines, marched"}},
        {"effects.godrays.march_steps=0", {"effects.godrays.march_steps: 0 is out of range", "1 <= value <= 4096"}},
        {"effects.godrays.grdi=64", {"effects.godrays.grdi: unknown field", "did you mean 'grid'"}},
    };
    for (const auto& [override_text, expected] : cases) {
        const std::string message = error_of(override_text);
        EXPECT_NE(message.find("godrays_needs_test.json"), std::string::npos) << message;
        for (const std::string& part : expected) EXPECT_NE(message.find(part), std::string::npos) << message;
    }
}

}  // namespace
}  // namespace vkw
