// The viewer's measurements (tools/vkwater/view/frame_stats.hpp): medians, warm-up and
// deliberately waiting frames left out of the frame time, per-pass medians over the timing
// frames each pass ran in.
#include "tools/vkwater/view/frame_stats.hpp"

#include <gtest/gtest.h>

namespace vkw::window {
namespace {

// The summary's line that starts with `start`, or "" if none.
std::string line_of(const std::string& text, const std::string& start) {
    for (size_t begin = 0; begin < text.size();) {
        const size_t end = std::min(text.find('\n', begin), text.size());
        if (text.compare(begin, start.size(), start) == 0) return text.substr(begin, end - begin);
        begin = end + 1;
    }
    return "";
}

TEST(FrameStats, MedianOfOddAndEvenCounts) {
    EXPECT_EQ(median({3.0, 1.0, 2.0}), 2.0);
    EXPECT_EQ(median({4.0, 1.0, 3.0, 2.0}), 2.5);
    EXPECT_EQ(median({}), 0.0);
}

TEST(FrameStats, WarmUpAndWaitingFramesAreNotCounted) {
    FrameStats stats;
    for (uint32_t i = 0; i < FrameStats::kWarmupFrames; ++i) stats.add_frame(1000.0, true);  // compiling shaders
    stats.add_frame(10.0, true);
    stats.add_frame(500.0, false);  // a timing frame
    stats.add_frame(30.0, true);
    stats.add_frame(20.0, true);
    EXPECT_EQ(stats.recent_frame_ms(), 20.0);
    const std::string summary = stats.summary(8);
    EXPECT_NE(summary.find("frames: 8; frame time over 3 intervals: median 20.00 ms (50.00 fps), mean 20.00 ms"),
              std::string::npos)
        << summary;
}

TEST(FrameStats, MediansSeeTheLastValuesAndTheMeanSeesAll) {
    // A viewer left running keeps kSummaryValues intervals, not one per frame: after twice that
    // many intervals of 10 ms and then kSummaryValues of 30 ms, the median is 30 ms (the last
    // values only) and the mean over all of them (10 + 10 + 30) / 3 = 16.67 ms.
    FrameStats stats;
    constexpr size_t n = FrameStats::kSummaryValues;
    for (uint32_t i = 0; i < FrameStats::kWarmupFrames; ++i) stats.add_frame(1000.0, true);
    for (size_t i = 0; i < 2 * n; ++i) stats.add_frame(10.0, true);
    for (size_t i = 0; i < n; ++i) stats.add_frame(30.0, true);
    const std::string summary = stats.summary(3 * n + FrameStats::kWarmupFrames + 1);
    EXPECT_NE(summary.find("frame time over 30000 intervals: median (of the last 10000) 30.00 ms (33.33 fps), "
                           "mean 16.67 ms (60.00 fps)"),
              std::string::npos)
        << summary;
}

TEST(RecentValues, KeepsTheLastCapacityValuesInOrder) {
    RecentValues values(3);
    for (double v : {1.0, 2.0, 3.0, 4.0, 5.0}) values.add(v);
    EXPECT_EQ(values.values(), (std::vector<double>{3.0, 4.0, 5.0}));
}

TEST(FrameStats, PassMediansCountTheFramesEachPassRanIn) {
    FrameStats stats;
    fg::FrameReport a;
    a.method = fg::TimingMode::Fences;
    a.passes = {{"sky", 1.0}, {"caustic photons", 10.0}};
    a.total_ms = 11.0;
    fg::FrameReport b = a;
    b.passes = {{"sky", 3.0}};
    b.total_ms = 3.0;
    stats.add_timing(a, 2.0, 10);
    stats.add_timing(b, 4.0, 20);
    stats.add_timing(a, 2.0, 30);
    const std::string summary = stats.summary(31);
    EXPECT_NE(summary.find("median of 3 timing frames (one submission per pass, fence-timed on the CPU clock)"),
              std::string::npos)
        << summary;
    EXPECT_NE(line_of(summary, "  sky ").find(" 1.00 ms"), std::string::npos) << summary;
    EXPECT_EQ(line_of(summary, "  sky ").find("(ran in"), std::string::npos) << summary;
    EXPECT_NE(line_of(summary, "  caustic photons ").find(" 10.00 ms  (ran in 2 of them)"), std::string::npos)
        << summary;
    EXPECT_NE(line_of(summary, "  present ").find(" 2.00 ms"), std::string::npos) << summary;
    EXPECT_EQ(stats.last_timing_frame(), 30u);
}

}  // namespace
}  // namespace vkw::window
