// The frame-time budget (vkwater render/view --budget-ms): among the candidate settings
// (quality.hpp), the one with the lowest predicted error (error_model.hpp) whose predicted time
// (cost_model.hpp) fits the budget.
//
// The viewer feeds it every counted frame's interval and, every few frames, a per-pass timing;
// it answers whether to change the setting. Changes are throttled so that the picture does not
// flicker between settings:
//   - a setting is judged on the median of the frames since it began, after kSettleFrames, or
//     after kQuickFrames when that median is more than kFarOverFactor times the budget (the
//     scene's own settings on a slow device: seconds a frame should not last six frames);
//   - over the budget it steps down at once, to the best candidate predicted within
//     kTargetFraction of it (the cheapest if none is);
//   - it steps up only when the median stays below kUpgradeFraction of the budget for
//     kUpgradeFrames, to a candidate predicted within kTargetFraction, and only for a lower
//     predicted error;
//   - a setting measured over the budget is not stepped up to again for kBanFrames frames;
//   - a step up that is measured over the budget stops every step up for kBanFrames frames: the
//     model had underestimated what the step adds, and the candidates near it share that error
//     (the showcase pool, stepping up from its scene lookups off to the refraction's lookup on,
//     tried one such candidate after another, its walls appearing and going every 8-30 frames).
#pragma once

#include "tools/vkwater/budget/cost_model.hpp"
#include "tools/vkwater/budget/error_model.hpp"
#include "tools/vkwater/budget/quality.hpp"

#include <cstdint>
#include <functional>
#include <map>
#include <optional>
#include <string>
#include <vector>

namespace vkw::budget {

struct Choice {
    Quality quality;
    double predicted_ms = 0.0;
    ErrorPrediction error;
};

class BudgetController {
public:
    static constexpr uint32_t kSettleFrames = 6;
    static constexpr uint32_t kQuickFrames = 3;
    static constexpr double kFarOverFactor = 2.0;
    static constexpr uint32_t kWindowFrames = 15;
    static constexpr uint32_t kUpgradeFrames = 30;
    static constexpr uint32_t kBanFrames = 300;
    static constexpr double kTargetFraction = 0.85;
    static constexpr double kUpgradeFraction = 0.7;

    // `drivers` gives a candidate's cost drivers (cost_drivers() for the scene and output size),
    // `output_rows` the output's height in pixels (the error model's resolution term follows it).
    BudgetController(double budget_ms, const Quality& top, std::function<CostDrivers(const Quality&)> drivers,
                     std::function<double()> output_rows);

    double budget_ms() const { return budget_ms_; }
    const Quality& current() const { return current_; }
    const Quality& top() const { return top_; }
    const CostModel& model() const { return model_; }

    // A per-pass timing of a frame at current().
    void add_pass_times(const std::vector<fg::PassTime>& passes);
    // A frame's interval (or its fence time) at current(). Returns true when it changed current():
    // the caller renders the next frame with it.
    bool add_frame(double ms);

    // A one-shot plan (vkwater render --budget-ms): a timed frame at current() fits the model, and
    // plan() is the candidate to render next; set_current() makes it current(). It aims at the
    // budget itself, not kTargetFraction of it: the render times every setting it plans and keeps
    // only one that measured within the budget, where the viewer's margin is for frames to come.
    void add_timed_frame(const std::vector<fg::PassTime>& passes, double frame_ms);
    Choice plan() const { return choose(budget_ms_); }
    void set_current(const Quality& quality) { change_to(quality); }
    // A new top for the same scene (the viewer's previews made again where its camera rests: the
    // on/off knobs' measured terms, and the needs there). The candidates follow it; the cost model,
    // fitted to this device's passes, and the setting in force stay, where the setting is still a
    // candidate. Returns true when it is not and current() changed to the best one predicted
    // within the budget.
    bool retarget(const Quality& top);

    // The best candidate predicted within `limit_ms`, or the cheapest when none is.
    Choice choose(double limit_ms) const;
    Choice describe(const Quality& quality) const;  // its predicted time and error
    // The median frame time measured at current() so far (0 before any frame).
    double measured_ms() const;
    uint64_t changes() const { return changes_; }
    // "budget 66 ms: 58 ms measured, 55 predicted; relMSE +0.048 (resolution scale)".
    std::string status() const;

private:
    void change_to(const Quality& quality);
    void set_top(const Quality& top);  // with its candidates, and nothing kept of the last top's
    double budget_ms_;
    Quality top_;
    std::function<CostDrivers(const Quality&)> drivers_;
    std::function<double()> output_rows_;
    std::vector<Quality> candidates_;
    // What choose() needs of each candidate that the timings do not change: its cost drivers, and
    // its predicted error at the output's rows (`error_rows_`; made again when they change).
    std::vector<CostDrivers> candidate_drivers_;
    mutable std::vector<double> candidate_errors_;
    mutable double error_rows_ = -1.0;
    // Each candidate's passes' predicted sum, before the frame factor, as of the cost model's
    // `passes_revision_`: only a per-pass timing refits the passes, every 30 frames, while the
    // frame factor moves with every frame.
    mutable std::vector<double> candidate_passes_ms_;
    mutable uint64_t passes_revision_ = ~uint64_t{0};
    CostModel model_;
    Quality current_;
    std::vector<double> frames_at_current_;
    uint64_t frame_ = 0;
    uint64_t changes_ = 0;
    std::map<size_t, uint64_t> banned_until_;  // candidate index -> frame
    bool stepped_up_ = false;                  // current() was reached by a step up
    uint64_t no_step_up_until_ = 0;            // frame
};

}  // namespace vkw::budget
