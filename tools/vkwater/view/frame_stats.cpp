#include "tools/vkwater/view/frame_stats.hpp"

#include <algorithm>
#include <cstdio>
#include <numeric>

namespace vkw::window {

double median(std::vector<double> values) {
    if (values.empty()) return 0.0;
    const size_t mid = values.size() / 2;
    std::nth_element(values.begin(), values.begin() + mid, values.end());
    const double upper = values[mid];
    if (values.size() % 2 == 1) return upper;
    return 0.5 * (upper + *std::max_element(values.begin(), values.begin() + mid));
}

void RecentValues::add(double value) {
    values_.push_back(value);
    if (values_.size() > capacity_) values_.pop_front();
}

void FrameStats::add_frame(double interval_ms, bool counted) {
    // Interval i runs from frame i to frame i + 1: the first kWarmupFrames start in warm-up.
    const bool warm_up = intervals_++ < kWarmupFrames;
    if (!counted || warm_up) return;
    ++counted_;
    counted_sum_ms_ += interval_ms;
    counted_ms_.add(interval_ms);
    recent_ms_.add(interval_ms);
}

void FrameStats::add_timing(const fg::FrameReport& report, double present_ms, uint64_t frame) {
    ++timing_frames_;
    last_report_ = report;
    last_present_ms_ = present_ms;
    last_timing_frame_ = frame;
    method_ = report.method_name();
    for (const fg::PassTime& pass : report.passes) {
        auto slot = std::find_if(pass_ms_.begin(), pass_ms_.end(), [&](const auto& p) { return p.name == pass.pass; });
        if (slot == pass_ms_.end()) slot = pass_ms_.insert(pass_ms_.end(), PassSeries{pass.pass});
        ++slot->timing_frames;
        slot->ms.add(pass.ms);
    }
    present_ms_.add(present_ms);
    total_ms_.add(report.total_ms + present_ms);
}

double FrameStats::recent_frame_ms() const {
    if (recent_ms_.empty()) return 0.0;
    const std::vector<double> recent = recent_ms_.values();
    return std::accumulate(recent.begin(), recent.end(), 0.0) / static_cast<double>(recent.size());
}

std::string FrameStats::summary(uint64_t frames) const {
    char line[256];
    std::string text;
    if (counted_ == 0) {
        std::snprintf(line, sizeof line, "frames: %llu, too few to time (the first %u are warm-up)\n",
                      static_cast<unsigned long long>(frames), kWarmupFrames);
        text += line;
    } else {
        const double med = median(counted_ms_.values());
        const double mean = counted_sum_ms_ / static_cast<double>(counted_);
        const std::string median_of =
            counted_ > counted_ms_.size() ? " (of the last " + std::to_string(counted_ms_.size()) + ")" : "";
        std::snprintf(line, sizeof line,
                      "frames: %llu; frame time over %llu intervals: median%s %.2f ms (%.2f fps), mean %.2f ms "
                      "(%.2f fps)\n",
                      static_cast<unsigned long long>(frames), static_cast<unsigned long long>(counted_),
                      median_of.c_str(), med, 1000.0 / med, mean, 1000.0 / mean);
        text += line;
    }
    if (timing_frames_ == 0) return text + "per-pass times: no timing frame ran\n";
    const std::string last = timing_frames_ > kSummaryValues ? ", the last " + std::to_string(kSummaryValues) : "";
    std::snprintf(line, sizeof line, "per-pass times, median of %llu timing frames%s (%s):\n",
                  static_cast<unsigned long long>(timing_frames_), last.c_str(), method_.c_str());
    text += line;
    for (const PassSeries& pass : pass_ms_) {
        std::snprintf(line, sizeof line, "  %-28s %9.2f ms", pass.name.c_str(), median(pass.ms.values()));
        text += line;
        if (pass.timing_frames != timing_frames_) {
            std::snprintf(line, sizeof line, "  (ran in %llu of them)",
                          static_cast<unsigned long long>(pass.timing_frames));
            text += line;
        }
        text += "\n";
    }
    std::snprintf(line, sizeof line, "  %-28s %9.2f ms  (tonemap + overlay: one submission, fence-timed)\n", "present",
                  median(present_ms_.values()));
    text += line;
    std::snprintf(line, sizeof line, "  %-28s %9.2f ms  (sum of the above, each timing frame)\n", "frame",
                  median(total_ms_.values()));
    return text + line;
}

}  // namespace vkw::window
