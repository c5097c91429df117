// The godrays' needs rule (passes/frame/frame_needs.cpp), one test per reason, and their scene
// fields (effects.godrays in scenes/README.md): defaults, every field read, each out-of-range value
// refused naming the field and the accepted range. No GPU.
#include "engine/image/tone_curve.hpp"
#include "engine/scene/scene_loader.hpp"
#include "engine/water/beam_modulation_bound.hpp"
#include "engine/water/surface.hpp"
#include "passes/frame/frame_needs.hpp"
#include "passes/godrays/godrays.hpp"
#include "tools/reference/caustic_in_scatter.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>
#include <thread>
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

// The threshold of the waves' rule: the largest relative change of a pixel's radiance that moves
// no channel of the PNG preview by half a step, whatever the exposure. The preview's steepest
// point in log radiance, found by sampling (1e-5 to 1e3, 40000 points per decade, central
// differences of step 1e-4 relative in the exact curve evaluated in double): about 72.9 steps per
// unit of ln L, so 0.5 / 72.9 = 0.006857 is the largest such change; kGodraysInvisibleChange is
// below it.
TEST(godrays_needs, TheInvisibleChangeMovesNoPreviewStepByHalf) {
    auto preview = [](double x) {
        const double a = 2.51, b = 0.03, c = 2.43, d = 0.59, e = 0.14;
        const double tone = std::clamp((x * (a * x + b)) / (x * (c * x + d) + e), 0.0, 1.0);
        return 255.0 * (tone <= 0.0031308 ? 12.92 * tone : 1.055 * std::pow(tone, 1.0 / 2.4) - 0.055);
    };
    // The double curve is the float one of the preview (engine/image/tone_curve.hpp) at a few points.
    for (double x : {0.01, 0.169, 1.0, 4.0}) {
        EXPECT_NEAR(preview(x) / 255.0, linear_to_srgb(aces_narkowicz(float(x))), 1e-6) << x;
    }
    double steepest = 0.0;
    for (int i = 0; i <= 8 * 40000; ++i) {
        const double x = std::pow(10.0, -5.0 + i / 40000.0), h = 1e-4;
        steepest = std::max(steepest, (preview(x * (1.0 + h)) - preview(x * (1.0 - h))) / (2.0 * h));
    }
    EXPECT_NEAR(steepest, 72.9, 0.1);
    EXPECT_LE(kGodraysInvisibleChange * steepest, 0.5);
    EXPECT_GT(kGodraysInvisibleChange * steepest, 0.49);  // and not needlessly strict
}

// The scene's waves at amplitude A: one sine of wavelength 4 m, so that millimetre waves keep the
// beams within a fraction of a percent of flat water's (2 m deep, sun 60 degrees high).
std::vector<std::string> gentle_sine(double amplitude) {
    return {R"(water.waves={"model": "sum", "components": [{"amplitude": )" + std::to_string(amplitude) +
            R"(, "wavelength": 4, "direction_deg": 20}]})"};
}

double bound_for_amplitude(double amplitude) {
    const Scene scene = scene_with(gentle_sine(amplitude));
    const auto surface = make_surface(scene.water->waves, 0.0, 0.0);
    const glm::dvec3 sigma_t = scene.medium.sigma_t();
    return beam_modulation_bound({scene.sun.direction, scene.water->ior, surface->max_amplitude(), surface->max_slope(),
                                  surface->max_curvature(), 2.0, std::max({sigma_t.x, sigma_t.y, sigma_t.z})})
        .largest_relative_change();
}

TEST(godrays_needs, CulledJustBelowTheWavesBoundAndKeptJustAbove) {
    // The amplitude at which the bound reaches the threshold, by bisection (it grows with A).
    double lo = 0.0, hi = 0.01;
    ASSERT_GT(bound_for_amplitude(hi), kGodraysInvisibleChange);
    for (int i = 0; i < 60; ++i) {
        const double mid = 0.5 * (lo + hi);
        (bound_for_amplitude(mid) > kGodraysInvisibleChange ? hi : lo) = mid;
    }
    ASSERT_GT(lo, 1e-4);  // millimetres: the bound is not vacuous
    const auto below = godrays(needs_of(gentle_sine(0.97 * lo)));
    EXPECT_FALSE(below.needed) << below.reason;
    EXPECT_TRUE(says(below, "stands in")) << below.reason;
    const auto above = godrays(needs_of(gentle_sine(1.03 * lo)));
    EXPECT_TRUE(above.needed) << above.reason;
    EXPECT_TRUE(says(above, "in-scatter change of at most")) << above.reason;
}

// The waves' bound is kept, per thread, while its inputs stay (passes/frame/frame_needs.cpp): a
// running clock reuses it, and any other input changed alone must make it again. Each variant is
// decided right after the base scene, and on a new thread, whose kept bound is empty: the two
// decisions must be the same, and differ from the base's wherever the input is one the bound reads.
TEST(godrays_needs, TheWavesBoundKeptWhileTheClockRunsFollowsEveryOtherInput) {
    const auto sine = [](const std::string& fields) {
        return R"(water.waves={"model": "sum", "components": [{)" + fields + "}]}";
    };
    const std::string base_waves = R"("amplitude": 0.002, "wavelength": 4, "direction_deg": 20)";
    const std::vector<std::string> base = {sine(base_waves)};
    struct Variant {
        std::vector<std::string> overrides;
        bool moves_the_bound;
    };
    const std::vector<Variant> variants = {
        {{sine(base_waves), "water.time=7"}, false},
        {{sine(base_waves + R"(, "phase_deg": 90)")}, false},
        {{sine(R"("amplitude": 0.003, "wavelength": 4, "direction_deg": 20)")}, true},
        {{sine(R"("amplitude": 0.002, "wavelength": 3, "direction_deg": 20)")}, true},
        {{sine(R"("amplitude": 0.002, "wavelength": 4, "direction_deg": 20, "steepness": 0.05)")}, true},
        {{sine(base_waves), "sun.elevation_deg=40"}, true},
        {{sine(base_waves), "water.ior=1.4"}, true},
        {{sine(base_waves), "floor.height=-3"}, true},
        {{sine(base_waves), "medium.preset=turbid-harbour"}, true},
    };
    const fg::EffectDecision base_decision = godrays(needs_of(base));
    ASSERT_TRUE(says(base_decision, "in-scatter change of at most")) << base_decision.reason;
    for (const Variant& variant : variants) {
        std::string where;
        for (const std::string& o : variant.overrides) where += o + " ";
        (void)needs_of(base);  // the base's bound kept
        const fg::EffectDecision kept = godrays(needs_of(variant.overrides));
        fg::EffectDecision fresh;
        std::thread([&] { fresh = godrays(needs_of(variant.overrides)); }).join();
        EXPECT_EQ(kept.needed, fresh.needed) << where;
        EXPECT_EQ(kept.reason, fresh.reason) << where;
        if (variant.moves_the_bound) {
            EXPECT_NE(fresh.reason, base_decision.reason) << where;
        } else {
            EXPECT_EQ(fresh.reason, base_decision.reason) << where;
        }
    }
}

TEST(godrays_needs, NeededWhereTheBeamsFocusOrTheModelGivesNoBound) {
    const auto focusing = godrays(needs_of({}));  // A k = 0.31 over 2 m: a caustic forms
    EXPECT_TRUE(focusing.needed);
    EXPECT_TRUE(says(focusing, "caustic can form")) << focusing.reason;
    const auto gerstner = godrays(needs_of(
        {R"(water.waves={"model": "sum", "components": [{"amplitude": 1e-4, "wavelength": 4, "steepness": 0.1}]})"}));
    EXPECT_TRUE(gerstner.needed);
    EXPECT_TRUE(says(gerstner, "no bound")) << gerstner.reason;
    const auto stopped = godrays(needs_of({"water.waves=null", "effects.godrays.max_depth=1"}));
    EXPECT_TRUE(stopped.needed);
    EXPECT_TRUE(says(stopped, "max_depth")) << stopped.reason;
}

// The bound against the reference's own modulation m (the beam-mapped irradiance on planes down to
// the floor over flat water's: tools/reference/caustic_in_scatter.hpp), for a sine whose bound is
// far from 1, with the sun oblique: every sampled m lies within it, and the largest |m - 1| seen
// is more than a quarter of the bound's (so the bound is not vacuous). Texel averages of m can only
// lie inside the extremes of m, so the containment is exact; measured: m from 0.787 to 1.375 against
// the bound's 0.554 to 2.213 (0.31 of the bound's deviation: the bound counts the slope's terms
// and the focusing apart, and takes K at its largest).
TEST(godrays_needs, TheWavesBoundHoldsAgainstTheReferenceModulation) {
    const double wavelength = 0.5, k = 2.0 * std::numbers::pi / wavelength, amplitude = 0.005;
    const Scene scene = parse_scene(R"({
      "camera": {"position": [0, 2, 3], "target": [0, 0, 0]},
      "sun": {"elevation_deg": 60, "azimuth_deg": 90, "irradiance": [2, 2, 2]},
      "sky": {"radiance": [0, 0, 0]},
      "floor": {"height": -1, "half_extent": 4},
      "water": {"level": 0, "half_extent": 1, "ior": 1.333,
                "waves": {"model": "sum", "components": [{"amplitude": 0.005, "wavelength": 0.5}]}},
      "medium": {"sigma_a": [0.1, 0.2, 0.4], "sigma_s": [0.3, 0.3, 0.3], "g": 0.9}
    })",
                                    "bound.json");
    const auto surface = make_surface(scene.water->waves, 0.0, 0.0);
    EXPECT_NEAR(surface->max_curvature(), amplitude * k * k, 1e-12);
    const BeamModulationBound bound = beam_modulation_bound({scene.sun.direction, 1.333, surface->max_amplitude(),
                                                             surface->max_slope(), surface->max_curvature(), 1.0, 0.7});
    ASSERT_TRUE(bound.bounded) << bound.unbounded_because;
    const ref::CausticInScatter in_scatter(scene, *surface, amplitude, {9, 512, 1024, 0.0});
    double lowest = 1e300, highest = 0.0;
    // Away from the water's edges (the beams there come from outside the water), at every plane.
    for (double depth : in_scatter.plane_depths()) {
        for (int i = 0; i <= 160; ++i) {
            const glm::dvec3 m = in_scatter.modulation({-0.4 + 0.8 * i / 160.0, -depth, 0.0});
            for (int c = 0; c < 3; ++c) {
                lowest = std::min(lowest, m[c]);
                highest = std::max(highest, m[c]);
            }
        }
    }
    EXPECT_GE(lowest, bound.low);
    EXPECT_LE(highest, bound.high);
    EXPECT_GT(std::max(highest - 1.0, 1.0 - lowest), 0.25 * std::max(bound.high - 1.0, 1.0 - bound.low))
        << "m from " << lowest << " to " << highest << ", bound " << bound.low << " to " << bound.high;
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
    EXPECT_EQ(defaults.resolution_scale, 0.5);
    EXPECT_FALSE(defaults.max_depth.has_value());
    EXPECT_EQ(defaults.method, GodrayMethod::Lines);
    EXPECT_EQ(defaults.march_steps, 32u);
    const GodraySettings set =
        scene_with({"effects.godrays.grid=256", "effects.godrays.resolution_scale=1", "effects.godrays.max_depth=7.5",
                    "effects.godrays.method=marched", "effects.godrays.march_steps=9", "effects.godrays.mode=on"})
            .effects.godrays;
    EXPECT_EQ(set.grid, 256u);
    EXPECT_EQ(set.resolution_scale, 1.0);
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
        {"effects.godrays.max_depth=0", {"effects.godrays.max_depth: 0 is out of range", "0 < value <= 1e+05 m"}},
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
