// The frame-time budget's controller (budget_controller.hpp).
#include "tools/vkwater/budget/budget_controller.hpp"

#include <algorithm>
#include <cstdio>

namespace vkw::budget {
namespace {

double median_of(std::vector<double> values) {
    if (values.empty()) return 0.0;
    const size_t middle = values.size() / 2;
    std::nth_element(values.begin(), values.begin() + middle, values.end());
    return values[middle];
}

}  // namespace

BudgetController::BudgetController(double budget_ms, const Quality& top,
                                   std::function<CostDrivers(const Quality&)> drivers,
                                   std::function<double()> output_rows)
    : budget_ms_(budget_ms), drivers_(std::move(drivers)), output_rows_(std::move(output_rows)), current_(top) {
    set_top(top);
}

void BudgetController::set_top(const Quality& top) {
    top_ = top;
    candidates_ = quality_candidates(top);
    candidate_drivers_.clear();
    candidate_drivers_.reserve(candidates_.size());
    for (const Quality& candidate : candidates_) candidate_drivers_.push_back(drivers_(candidate));
    // What choose() kept per candidate, and the bans, are by index into the old candidates.
    candidate_errors_.clear();
    error_rows_ = -1.0;
    candidate_passes_ms_.clear();
    passes_revision_ = ~uint64_t{0};
    banned_until_.clear();
}

bool BudgetController::retarget(const Quality& top) {
    set_top(top);
    // The same knobs under the new top: the measured terms are the same in every candidate.
    Quality same = current_;
    same.measured_off = top.measured_off;
    same.caustic_visibility = top.caustic_visibility;
    same.camera_in_water = top.camera_in_water;
    if (std::find(candidates_.begin(), candidates_.end(), same) != candidates_.end()) {
        current_ = same;
        return false;
    }
    change_to(choose(kTargetFraction * budget_ms_).quality);
    stepped_up_ = false;
    return true;
}

Choice BudgetController::describe(const Quality& quality) const {
    Choice choice;
    choice.quality = quality;
    choice.predicted_ms = model_.predict_ms(drivers_(quality), quality.godray_grid > 0, quality.render_scale < 1.0);
    choice.error = predict_error(quality, top_, output_rows_());
    return choice;
}

Choice BudgetController::choose(double limit_ms) const {
    // The viewer asks on every frame over the budget: each candidate's error and drivers are made
    // once, and only its time is predicted again from the model as timed so far.
    const double rows = output_rows_();
    if (rows != error_rows_) {
        candidate_errors_.clear();
        for (const Quality& candidate : candidates_)
            candidate_errors_.push_back(predict_error(candidate, top_, rows).excess);
        error_rows_ = rows;
    }
    if (model_.passes_revision() != passes_revision_) {
        candidate_passes_ms_.clear();
        for (size_t i = 0; i < candidates_.size(); ++i) {
            const Quality& candidate = candidates_[i];
            candidate_passes_ms_.push_back(model_.predict_passes_ms(candidate_drivers_[i], candidate.godray_grid > 0,
                                                                    candidate.render_scale < 1.0));
        }
        passes_revision_ = model_.passes_revision();
    }
    std::optional<size_t> best, cheapest;
    double best_ms = 0.0, cheapest_ms = 0.0;
    for (size_t i = 0; i < candidates_.size(); ++i) {
        const Quality& candidate = candidates_[i];
        const double ms = model_.frame_factor() * candidate_passes_ms_[i];  // as predict_ms makes it
        if (!cheapest || ms < cheapest_ms) {
            cheapest = i;
            cheapest_ms = ms;
        }
        const auto ban = banned_until_.find(i);
        if (ban != banned_until_.end() && frame_ < ban->second && candidate != current_) continue;
        if (ms > limit_ms) continue;
        // The lowest error; at equal error the cheaper.
        const double error = candidate_errors_[i];
        if (!best || error < candidate_errors_[*best] || (error == candidate_errors_[*best] && ms < best_ms)) {
            best = i;
            best_ms = ms;
        }
    }
    return describe(candidates_[best ? *best : *cheapest]);
}

void BudgetController::add_pass_times(const std::vector<fg::PassTime>& passes) {
    model_.observe_passes(passes, drivers_(current_));
}

void BudgetController::add_timed_frame(const std::vector<fg::PassTime>& passes, double frame_ms) {
    const CostDrivers drivers = drivers_(current_);
    model_.observe_passes(passes, drivers);
    model_.observe_frame(frame_ms, drivers);
    frames_at_current_.push_back(frame_ms);
}

double BudgetController::measured_ms() const {
    const size_t count = std::min<size_t>(frames_at_current_.size(), kWindowFrames);
    return median_of(std::vector<double>(frames_at_current_.end() - count, frames_at_current_.end()));
}

void BudgetController::change_to(const Quality& quality) {
    current_ = quality;
    frames_at_current_.clear();
    ++changes_;
}

bool BudgetController::add_frame(double ms) {
    ++frame_;
    frames_at_current_.push_back(ms);
    // Judge a setting only once it has run a few frames, and predict only from a timed frame.
    if (frames_at_current_.size() < kQuickFrames || !model_.fitted()) return false;
    const double measured = measured_ms();
    if (frames_at_current_.size() < kSettleFrames && measured <= kFarOverFactor * budget_ms_) return false;
    model_.observe_frame(measured, drivers_(current_));
    if (measured > budget_ms_) {
        const size_t index = std::find(candidates_.begin(), candidates_.end(), current_) - candidates_.begin();
        banned_until_[index] = frame_ + kBanFrames;
        if (stepped_up_) no_step_up_until_ = frame_ + kBanFrames;
        const Choice next = choose(kTargetFraction * budget_ms_);
        if (next.quality == current_) return false;  // already the cheapest there is
        change_to(next.quality);
        stepped_up_ = false;
        return true;
    }
    if (measured < kUpgradeFraction * budget_ms_ && frames_at_current_.size() >= kUpgradeFrames &&
        frame_ >= no_step_up_until_) {
        const Choice next = choose(kTargetFraction * budget_ms_);
        if (next.error.excess >= predict_error(current_, top_, output_rows_()).excess) return false;
        change_to(next.quality);
        stepped_up_ = true;
        return true;
    }
    return false;
}

std::string BudgetController::status() const {
    const Choice now = describe(current_);
    char text[256];
    std::snprintf(text, sizeof text, "budget %.1f ms: %.1f ms measured, %.1f predicted; relMSE +%.3g%s%s%s", budget_ms_,
                  measured_ms(), now.predicted_ms, now.error.excess, now.error.dominant.empty() ? "" : " (",
                  now.error.dominant.c_str(), now.error.dominant.empty() ? "" : ")");
    return text;
}

}  // namespace vkw::budget
