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
    : budget_ms_(budget_ms),
      top_(top),
      drivers_(std::move(drivers)),
      output_rows_(std::move(output_rows)),
      candidates_(quality_candidates(top)),
      current_(top) {}

Choice BudgetController::describe(const Quality& quality) const {
    Choice choice;
    choice.quality = quality;
    choice.predicted_ms = model_.predict_ms(drivers_(quality), quality.godray_grid > 0, quality.render_scale < 1.0);
    choice.error = predict_error(quality, top_, output_rows_());
    return choice;
}

Choice BudgetController::choose(double limit_ms) const {
    std::optional<Choice> best, cheapest;
    for (size_t i = 0; i < candidates_.size(); ++i) {
        const Choice choice = describe(candidates_[i]);
        if (!cheapest || choice.predicted_ms < cheapest->predicted_ms) cheapest = choice;
        const auto ban = banned_until_.find(i);
        if (ban != banned_until_.end() && frame_ < ban->second && candidates_[i] != current_) continue;
        if (choice.predicted_ms > limit_ms) continue;
        // The lowest error; at equal error the cheaper.
        if (!best || choice.error.excess < best->error.excess ||
            (choice.error.excess == best->error.excess && choice.predicted_ms < best->predicted_ms)) {
            best = choice;
        }
    }
    return best ? *best : *cheapest;
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
        const Choice next = choose(kTargetFraction * budget_ms_);
        if (next.quality == current_) return false;  // already the cheapest there is
        change_to(next.quality);
        return true;
    }
    if (measured < kUpgradeFraction * budget_ms_ && frames_at_current_.size() >= kUpgradeFrames) {
        const Choice next = choose(kTargetFraction * budget_ms_);
        if (next.error.excess >= predict_error(current_, top_, output_rows_()).excess) return false;
        change_to(next.quality);
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
