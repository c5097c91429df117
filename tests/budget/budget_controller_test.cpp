// The budget's controller against a scripted device: every pass costs its prior formula times a
// factor of the device's own (not the priors': the model must fit them), the whole frame a fixed
// fraction of the passes' sum (one submission against one per pass), with +-5% noise from a fixed
// sequence. Per-pass timings come every 30 frames and on the frame after each change, as the
// viewer gives them.
#include "tools/vkwater/budget/budget_controller.hpp"

#include "engine/scene/scene_loader.hpp"
#include "passes/frame/frame_needs.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <set>

namespace vkw::budget {
namespace {

constexpr uint32_t kWidth = 800, kHeight = 600;

// The passes pool runs at a setting, as the renderer names them.
std::vector<std::string> pool_passes(const Quality& q) {
    std::vector<std::string> names = {"upload frame constants",
                                      "scene optics",
                                      "water surface (wave sum)",
                                      "water mesh (wave sum)",
                                      "caustic flux clear",
                                      "caustic photons",
                                      "caustic resolve",
                                      "sky",
                                      "water",
                                      "floor",
                                      "calibration",
                                      "present handoff"};
    if (q.godray_grid > 0) {
        for (const char* name : {"godray depth", "godray beams", "godray clear", "godray lines", "godray resolve",
                                 "godray blur x", "godray blur y", "godray composite"}) {
            names.push_back(name);
        }
    }
    if (q.render_scale < 1.0) names.push_back("upscale");
    if (q.samples > 1) names.push_back("keep caustic map");
    return names;
}

class ScriptedDevice {
public:
    explicit ScriptedDevice(const Scene& scene) : scene_(scene) {}
    double load = 1.0;  // a step in the machine's load multiplies every pass

    // This device's factor over the priors: not one number, so that the frame's mix matters.
    static double device_factor(const std::string& pass) {
        if (pass == "water") return 1.6;
        if (pass == "caustic photons") return 0.7;
        if (pass.rfind("godray", 0) == 0) return 1.3;
        return 1.1;
    }
    std::vector<fg::PassTime> pass_times(const Quality& q) {
        const CostDrivers drivers = cost_drivers(scene_, q, kWidth, kHeight);
        std::vector<fg::PassTime> times;
        for (const std::string& name : pool_passes(q)) {
            const PassFormula formula = pass_formula(name);
            // (prior_ms counts every sub-frame the pass runs in; a pass without a formula runs in each.)
            const double ms =
                formula.ns_per_unit.empty() ? 0.1 * q.samples : device_factor(name) * formula.prior_ms(drivers);
            times.push_back({name, ms * load * noise()});
        }
        return times;
    }
    double frame_ms(const Quality& q) {
        double sum = 0.0;
        for (const fg::PassTime& pass : pass_times(q)) sum += pass.ms;
        return 0.8 * sum;  // one submission: faster than one per pass
    }
    // The frame time without noise: what the setting really costs.
    double true_frame_ms(const Quality& q) {
        const uint64_t saved = step_;
        noiseless_ = true;
        const double ms = frame_ms(q);
        noiseless_ = false;
        step_ = saved;
        return ms;
    }

private:
    double noise() {
        if (noiseless_) return 1.0;
        // A fixed sequence in [0.95, 1.05]: the golden-ratio walk modulo 1.
        step_ += 1;
        const double u = std::fmod(0.5 + 0.6180339887498949 * double(step_), 1.0);
        return 0.95 + 0.1 * u;
    }
    const Scene& scene_;
    uint64_t step_ = 0;
    bool noiseless_ = false;
};

// Pool, loaded once for every test here.
const Scene& pool() {
    static const Scene scene = load_scene(std::filesystem::path(VKWATER_SOURCE_DIR) / "scenes/pool.json");
    return scene;
}

// A controller of pool at 800x600 under `budget_ms`, at the scene's own settings.
BudgetController pool_controller(double budget_ms) {
    return BudgetController(
        budget_ms, scene_quality(pool(), decide_frame_needs(pool(), 4.0 / 3.0)),
        [](const Quality& q) { return cost_drivers(pool(), q, kWidth, kHeight); }, [] { return double(kHeight); });
}

struct BudgetRun {
    std::vector<Quality> settings;  // the setting of each frame
    uint64_t changes = 0;
};

// `frames` frames of pool under `budget_ms`; `load_at(frame)` is the machine's load.
BudgetRun run_budget(double budget_ms, uint32_t frames, const std::function<double(uint32_t)>& load_at) {
    ScriptedDevice device(pool());
    BudgetController controller = pool_controller(budget_ms);
    BudgetRun run;
    uint64_t timing_due = 3;  // after the warm-up frames, as the viewer
    for (uint32_t frame = 0; frame < frames; ++frame) {
        device.load = load_at(frame);
        run.settings.push_back(controller.current());
        if (frame >= timing_due) {
            controller.add_pass_times(device.pass_times(controller.current()));
            timing_due = frame + 30;
        }
        if (controller.add_frame(device.frame_ms(controller.current()))) timing_due = frame + 1;
    }
    run.changes = controller.changes();
    return run;
}

double true_ms(const Quality& q, double load) {
    const Scene& scene = pool();
    ScriptedDevice device(scene);
    device.load = load;
    return device.true_frame_ms(q);
}

TEST(BudgetController, ConvergesUnderTheBudgetAndStays) {
    for (double budget : {66.0, 150.0, 400.0}) {
        const BudgetRun run = run_budget(budget, 600, [](uint32_t) { return 1.0; });
        // Settled within 120 frames: no change after, and under the budget.
        for (size_t f = 120; f < run.settings.size(); ++f) {
            EXPECT_EQ(run.settings[f], run.settings.back()) << "budget " << budget << ": changed at frame " << f;
        }
        EXPECT_LE(true_ms(run.settings.back(), 1.0), budget) << budget;
        // Without oscillating on the way: a handful of changes.
        EXPECT_LE(run.changes, 6u) << budget;
        // And it uses the budget: the scene's own settings take 550 ms here, so every budget
        // below that must turn something down, and none may sit at a tenth of it.
        EXPECT_GT(true_ms(run.settings.back(), 1.0), 0.25 * budget) << budget;
    }
}

TEST(BudgetController, ReactsToAStepInLoadWithinBoundedFrames) {
    const double budget = 100.0;
    const uint32_t step_at = 300;
    const BudgetRun run = run_budget(budget, 600, [](uint32_t frame) { return frame < step_at ? 1.0 : 2.0; });
    ASSERT_LE(true_ms(run.settings[step_at - 1], 1.0), budget);
    // The frames judged after the step: kSettleFrames to see it, then one change per settle at most.
    const uint32_t bound = 4 * BudgetController::kSettleFrames + BudgetController::kWindowFrames;
    EXPECT_LE(true_ms(run.settings[step_at + bound], 2.0), budget)
        << "still over the budget " << bound << " frames after the load doubled";
    for (size_t f = step_at + bound + 60; f < run.settings.size(); ++f) {
        EXPECT_EQ(run.settings[f], run.settings.back()) << "changed at frame " << f;
    }
}

TEST(BudgetController, NeverPicksASettingTheTableRanksWorseAtEqualCost) {
    ScriptedDevice device(pool());
    BudgetController controller = pool_controller(100.0);
    const Quality& top = controller.top();
    controller.add_pass_times(device.pass_times(top));
    const std::vector<Quality> candidates = quality_candidates(top);
    for (double limit : {20.0, 50.0, 100.0, 200.0, 400.0}) {
        const Choice chosen = controller.choose(limit);
        EXPECT_LE(chosen.predicted_ms, limit);
        for (const Quality& other : candidates) {
            const Choice alternative = controller.describe(other);
            if (alternative.predicted_ms <= chosen.predicted_ms) {
                EXPECT_GE(alternative.error.excess, chosen.error.excess)
                    << describe_quality(other) << " is as cheap and ranked better than "
                    << describe_quality(chosen.quality);
            }
        }
    }
}

TEST(BudgetController, TheFittedModelPredictsTheDevice) {
    const Scene& scene = pool();
    ScriptedDevice device(scene);
    const Quality top = scene_quality(scene, decide_frame_needs(scene, 4.0 / 3.0));
    CostModel model;
    const CostDrivers top_drivers = cost_drivers(scene, top, kWidth, kHeight);
    model.observe_passes(device.pass_times(top), top_drivers);
    model.observe_frame(device.true_frame_ms(top), top_drivers);
    // Every candidate with the godrays on and at full scale runs the timed frame's passes: the
    // prediction is the device's own cost within the timing's noise (5%).
    for (const Quality& q : quality_candidates(top)) {
        const double predicted =
            model.predict_ms(cost_drivers(scene, q, kWidth, kHeight), q.godray_grid > 0, q.render_scale < 1.0);
        const double truth = device.true_frame_ms(q);
        const double tolerance = q.godray_grid > 0 && q.render_scale == 1.0 ? 0.06 : 0.15;
        EXPECT_NEAR(predicted / truth, 1.0, tolerance) << describe_quality(q);
    }
}

// With --spp 4 the frame is 4 sub-frames, the photon map's passes in the first only: fitted at 4
// samples or at 1, the model predicts both. Fitted at one sample it has not timed the kept map's
// copy, and takes its prior at the device's typical factor (the wider tolerance).
TEST(BudgetController, TheFittedModelPredictsSupersampledFrames) {
    const Scene& scene = pool();
    ScriptedDevice device(scene);
    const Quality top = scene_quality(scene, decide_frame_needs(scene, 4.0 / 3.0), 4);
    ASSERT_EQ(top.samples, 4u);
    Quality one_sample = top;
    one_sample.samples = 1;
    for (const Quality& timed : {top, one_sample}) {
        CostModel model;
        const CostDrivers drivers = cost_drivers(scene, timed, kWidth, kHeight);
        model.observe_passes(device.pass_times(timed), drivers);
        model.observe_frame(device.true_frame_ms(timed), drivers);
        for (const Quality& q : quality_candidates(top)) {
            if (q.godray_grid == 0 || q.render_scale != 1.0) continue;  // the timed frame's passes run
            const double predicted = model.predict_ms(cost_drivers(scene, q, kWidth, kHeight), true, false);
            const double tolerance = q.samples == timed.samples ? 0.06 : 0.15;
            EXPECT_NEAR(predicted / device.true_frame_ms(q), 1.0, tolerance)
                << describe_quality(q) << ", timed at " << timed.samples << " spp";
        }
    }
    // The photons once: 4 samples cost less than 4 frames of one.
    const CostDrivers four = cost_drivers(scene, top, kWidth, kHeight);
    const CostDrivers one = cost_drivers(scene, one_sample, kWidth, kHeight);
    EXPECT_DOUBLE_EQ(pass_formula("caustic photons").prior_ms(four), pass_formula("caustic photons").prior_ms(one));
    EXPECT_DOUBLE_EQ(pass_formula("water").prior_ms(four), 4.0 * pass_formula("water").prior_ms(one));
}

// A step up measured over the budget stops every step up for kBanFrames frames, however cheap the
// frames after it: the model had underestimated what the step adds, and the next candidate up
// would share that error (the picture would flicker between the two). After the ban a step up may
// come again. Frame times are given directly, whatever the setting.
TEST(BudgetController, AStepUpMeasuredOverTheBudgetStopsStepsUpForABan) {
    ScriptedDevice device(pool());
    BudgetController controller = pool_controller(100.0);
    const Quality& top = controller.top();
    controller.add_pass_times(device.pass_times(top));
    const auto frames = [&](uint32_t count, double ms) {
        for (uint32_t i = 0; i < count; ++i) controller.add_frame(ms);
    };
    frames(BudgetController::kQuickFrames, 500.0);  // far over: down at once
    ASSERT_EQ(controller.changes(), 1u);
    frames(BudgetController::kUpgradeFrames, 30.0);  // well under: up
    ASSERT_EQ(controller.changes(), 2u);
    frames(BudgetController::kSettleFrames, 150.0);  // the step up is over: down again
    ASSERT_EQ(controller.changes(), 3u);
    frames(BudgetController::kBanFrames - 2 * BudgetController::kSettleFrames, 30.0);
    EXPECT_EQ(controller.changes(), 3u) << "stepped up again within the ban";
    frames(2 * BudgetController::kSettleFrames + 1, 30.0);
    EXPECT_EQ(controller.changes(), 4u) << "no step up after the ban";
}

// The viewer makes its previews again where the camera comes to rest, and hands the controller
// the new top (BudgetController::retarget). Pool's caustics measured invisible from one camera
// make "caustics off" a candidate, which a tight budget takes (the photons are pool's dearest
// pass); measured visible from the next camera, that candidate is gone, and the controller leaves
// it at once for one of the new candidates, keeping the cost model it fitted. The same top again
// keeps the setting in force.
TEST(BudgetController, APreviewMadeAgainWhereTheCameraRestsRetargetsTheCandidates) {
    Quality top = scene_quality(pool(), decide_frame_needs(pool(), 4.0 / 3.0));
    ASSERT_TRUE(top.caustics);
    top.measured_off.caustics = 0.0;
    top.measured_off.caustics_largest_change = 0.0;  // nothing visible: the knob is offered
    ScriptedDevice device(pool());
    BudgetController controller(
        66.0, top, [](const Quality& q) { return cost_drivers(pool(), q, kWidth, kHeight); },
        [] { return double(kHeight); });
    uint64_t timing_due = 3;
    const auto run_frames = [&](uint32_t count) {
        for (uint32_t frame = 0; frame < count; ++frame) {
            if (frame >= timing_due) {
                controller.add_pass_times(device.pass_times(controller.current()));
                timing_due = frame + 30;
            }
            if (controller.add_frame(device.frame_ms(controller.current()))) timing_due = frame + 1;
        }
    };
    run_frames(200);
    ASSERT_FALSE(controller.current().caustics) << "the tight budget kept the invisible caustics";
    const Quality settled = controller.current();
    const double predicted = controller.describe(settled).predicted_ms;

    EXPECT_FALSE(controller.retarget(top)) << "the same top changed the setting";
    EXPECT_EQ(controller.current(), settled);
    EXPECT_DOUBLE_EQ(controller.describe(settled).predicted_ms, predicted) << "the cost model was not kept";

    Quality visible = top;
    visible.measured_off.caustics = 0.01;
    visible.measured_off.caustics_largest_change = 1.0;  // the new camera sees them
    const uint64_t changes = controller.changes();
    EXPECT_TRUE(controller.retarget(visible));
    EXPECT_EQ(controller.changes(), changes + 1);
    EXPECT_TRUE(controller.current().caustics);
    EXPECT_EQ(controller.top(), visible);
    EXPECT_EQ(controller.current().measured_off, visible.measured_off);
    // Settled again under the budget among the new candidates, none without the caustics.
    run_frames(200);
    EXPECT_TRUE(controller.current().caustics);
    EXPECT_LE(device.true_frame_ms(controller.current()), 66.0);
}

// The second layer's pass runs only with the layer, and the water pass costs more with it. Fitted
// to a frame with the layer, the model predicts the frame without it from the same factors; fitted
// to one without, it takes the layer's pass at the device's typical factor.
TEST(BudgetController, TheSecondLayerCostsItsPassAndTheWatersExtra) {
    static const Scene scene = load_scene(std::filesystem::path(VKWATER_SOURCE_DIR) / "scenes/lake.json");
    Quality on = scene_quality(scene, decide_frame_needs(scene, 4.0 / 3.0));
    ASSERT_TRUE(on.second_layer);
    on.caustics = false;  // the frames below time no photon map
    Quality off = on;
    off.second_layer = false;
    const CostDrivers with = cost_drivers(scene, on, kWidth, kHeight);
    const CostDrivers without = cost_drivers(scene, off, kWidth, kHeight);
    const double pixels = double(kWidth) * kHeight;
    const PassFormula layer = pass_formula("refraction view second layer");
    // Its pixels and the receivers' triangles it draws again.
    const double triangles = with[static_cast<size_t>(Driver::ReceiverTriangles)];
    EXPECT_GT(triangles, 30000.0) << "lake's bed alone has 2 x 128^2";
    EXPECT_DOUBLE_EQ(layer.prior_ms(with), (50.0 * pixels + 550.0 * triangles) * 1e-6);
    EXPECT_DOUBLE_EQ(pass_formula("water").prior_ms(with) - pass_formula("water").prior_ms(without),
                     150.0 * pixels * 1e-6);

    // A device at twice the priors for the water, 1.5 times for the other passes (no godrays).
    const auto times = [&](const Quality& q) {
        const CostDrivers drivers = cost_drivers(scene, q, kWidth, kHeight);
        std::vector<fg::PassTime> passes = {
            {"water", 2.0 * pass_formula("water").prior_ms(drivers)},
            {"refraction view", 1.5 * pass_formula("refraction view").prior_ms(drivers)},
            {"mirrored reflection view", 1.5 * pass_formula("mirrored reflection view").prior_ms(drivers)},
            {"sky", 1.5 * pass_formula("sky").prior_ms(drivers)}};
        if (q.second_layer) passes.push_back({"refraction view second layer", 1.5 * layer.prior_ms(drivers)});
        return passes;
    };
    const auto sum = [](const std::vector<fg::PassTime>& passes) {
        double ms = 0.0;
        for (const fg::PassTime& pass : passes) ms += pass.ms;
        return ms;
    };
    for (const Quality& timed : {on, off}) {
        CostModel model;
        const CostDrivers drivers = cost_drivers(scene, timed, kWidth, kHeight);
        model.observe_passes(times(timed), drivers);
        model.observe_frame(sum(times(timed)), drivers);
        for (const Quality& q : {on, off}) {
            // Exact but for the layer's pass when it was not timed: taken at the typical factor of
            // the timed passes (the median of 2, 1.5, 1.5, 1.5: 1.5, this device's own for it).
            EXPECT_NEAR(model.predict_ms(cost_drivers(scene, q, kWidth, kHeight), false, false), sum(times(q)),
                        1e-9 * sum(times(q)))
                << "timed " << (timed.second_layer ? "with" : "without") << " the layer, predicting "
                << (q.second_layer ? "with" : "without");
        }
    }
}

// The scene lookups' views run only with their lookups, and each lookup costs the water pass its
// pixels and steps. Fitted to a frame with both lookups, the model predicts the frames with the
// reflected rays' lookup off and with both off from the same factors; fitted to one with both off,
// it takes the views' passes at the device's typical factor (the median of 2, 1.5, 1.5: 1.5, this
// device's own for them).
TEST(BudgetController, TheSceneLookupsCostTheirViewsAndTheWatersLookups) {
    static const Scene scene = load_scene(std::filesystem::path(VKWATER_SOURCE_DIR) / "scenes/lake.json");
    Quality both = scene_quality(scene, decide_frame_needs(scene, 4.0 / 3.0));
    ASSERT_TRUE(both.reflection_lookup && both.refraction_lookup);
    both.second_layer = false;
    both.lookup_steps = 8;
    both.caustics = false;  // the frames below time no photon map
    Quality refraction_only = both;
    refraction_only.reflection_lookup = false;
    Quality none = both;
    none.lookup_steps = 0;
    none.refraction_lookup = none.reflection_lookup = false;
    const double pixels = double(kWidth) * kHeight;
    const auto water_ms = [](const Quality& q) {
        return pass_formula("water").prior_ms(cost_drivers(scene, q, kWidth, kHeight));
    };
    // 200 ns a pixel and lookup, and 1.6 ns a pixel, lookup and step.
    EXPECT_DOUBLE_EQ(water_ms(both) - water_ms(refraction_only), (200.0 + 8 * 1.6) * pixels * 1e-6);
    EXPECT_DOUBLE_EQ(water_ms(refraction_only) - water_ms(none), (200.0 + 8 * 1.6) * pixels * 1e-6);

    const auto times = [&](const Quality& q) {
        const CostDrivers drivers = cost_drivers(scene, q, kWidth, kHeight);
        std::vector<fg::PassTime> passes = {{"water", 2.0 * pass_formula("water").prior_ms(drivers)},
                                            {"receivers", 1.5 * pass_formula("receivers").prior_ms(drivers)},
                                            {"sky", 1.5 * pass_formula("sky").prior_ms(drivers)}};
        if (q.reflection_lookup) {
            passes.push_back(
                {"mirrored reflection view", 1.5 * pass_formula("mirrored reflection view").prior_ms(drivers)});
        }
        if (q.refraction_lookup) {
            passes.push_back({"refraction view", 1.5 * pass_formula("refraction view").prior_ms(drivers)});
        }
        return passes;
    };
    EXPECT_EQ(times(both).size(), 5u);
    EXPECT_EQ(times(refraction_only).size(), 4u);
    EXPECT_EQ(times(none).size(), 3u);
    const auto sum = [](const std::vector<fg::PassTime>& passes) {
        double ms = 0.0;
        for (const fg::PassTime& pass : passes) ms += pass.ms;
        return ms;
    };
    for (const Quality& timed : {both, refraction_only, none}) {
        CostModel model;
        const CostDrivers drivers = cost_drivers(scene, timed, kWidth, kHeight);
        model.observe_passes(times(timed), drivers);
        model.observe_frame(sum(times(timed)), drivers);
        for (const Quality& q : {both, refraction_only, none}) {
            EXPECT_NEAR(model.predict_ms(cost_drivers(scene, q, kWidth, kHeight), false, false), sum(times(q)),
                        1e-9 * sum(times(q)))
                << "timed with " << timed.scene_lookups() << " lookups, predicting " << q.scene_lookups();
        }
    }
}

}  // namespace
}  // namespace vkw::budget
