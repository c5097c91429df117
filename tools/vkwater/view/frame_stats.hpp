// What the viewer measures, and the summary it prints at exit.
//
// Frame time is the interval between the starts of successive frames: with frames in flight
// that is the throughput (the slower of the CPU's work and the device's). Frames that wait on
// purpose (the per-pass timing frames, screenshots) and the warm-up frames (the first ones
// compile llvmpipe's shader variants) are kept out of it.
//
// Per-pass times come from the timing frames, run alone with FrameExecutor::execute(): on CPU
// devices each pass is its own submission, fence-timed on the CPU clock (lavapipe's timestamps
// leave out raster work); the report names the method. The present graph (tonemap and
// overlay) is timed as one submission on the CPU clock.
//
// Medians are over the last kSummaryValues values of each series, so that a viewer left running
// for days holds the same memory as one that ran a minute; the mean frame time is over all of them.
#pragma once

#include "engine/framegraph/executor.hpp"

#include <cstdint>
#include <deque>
#include <string>
#include <utility>
#include <vector>

namespace vkw::window {

// The last `capacity` values of a series: what a median over a bounded memory can see.
class RecentValues {
public:
    explicit RecentValues(size_t capacity) : capacity_(capacity) {}
    void add(double value);
    std::vector<double> values() const { return {values_.begin(), values_.end()}; }
    size_t size() const { return values_.size(); }
    bool empty() const { return values_.empty(); }

private:
    size_t capacity_;
    std::deque<double> values_;
};

class FrameStats {
public:
    static constexpr uint32_t kWarmupFrames = 3;
    static constexpr size_t kRecentFrames = 30;
    static constexpr size_t kSummaryValues = 10000;

    // The interval from one frame's start to the next one's; `counted`: the first of the two
    // neither waited on purpose nor is a warm-up frame.
    void add_frame(double interval_ms, bool counted);
    // A timing frame's report of the scene graph, and its present graph's time.
    void add_timing(const fg::FrameReport& report, double present_ms, uint64_t frame);

    double recent_frame_ms() const;  // mean over the last kRecentFrames counted frames; 0 before any
    bool has_timing() const { return timing_frames_ > 0; }
    const fg::FrameReport& last_report() const { return last_report_; }
    double last_present_ms() const { return last_present_ms_; }
    uint64_t last_timing_frame() const { return last_timing_frame_; }

    // The exit summary of `frames` frames: frame time and frame rate (median and mean of the
    // counted intervals), and each pass's median over the timing frames it ran in.
    std::string summary(uint64_t frames) const;

private:
    struct PassSeries {
        std::string name;
        uint64_t timing_frames = 0;  // the timing frames it ran in
        RecentValues ms{kSummaryValues};
    };

    uint64_t intervals_ = 0;
    uint64_t counted_ = 0;
    double counted_sum_ms_ = 0.0;
    RecentValues counted_ms_{kSummaryValues};
    RecentValues recent_ms_{kRecentFrames};
    uint64_t timing_frames_ = 0;
    fg::FrameReport last_report_;
    double last_present_ms_ = 0.0;
    uint64_t last_timing_frame_ = 0;
    std::string method_;
    std::vector<PassSeries> pass_ms_;  // first-seen order
    RecentValues present_ms_{kSummaryValues};
    RecentValues total_ms_{kSummaryValues};
};

double median(std::vector<double> values);

}  // namespace vkw::window
