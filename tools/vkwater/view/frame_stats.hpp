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
#pragma once

#include "engine/framegraph/executor.hpp"

#include <cstdint>
#include <deque>
#include <string>
#include <utility>
#include <vector>

namespace vkw::window {

class FrameStats {
public:
    static constexpr uint32_t kWarmupFrames = 3;
    static constexpr size_t kRecentFrames = 30;

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
    uint64_t intervals_ = 0;
    std::vector<double> counted_ms_;
    std::deque<double> recent_ms_;
    uint64_t timing_frames_ = 0;
    fg::FrameReport last_report_;
    double last_present_ms_ = 0.0;
    uint64_t last_timing_frame_ = 0;
    std::string method_;
    std::vector<std::pair<std::string, std::vector<double>>> pass_ms_;  // first-seen order
    std::vector<double> present_ms_;
    std::vector<double> total_ms_;
};

double median(std::vector<double> values);

}  // namespace vkw::window
