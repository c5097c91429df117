// Which frames a sequence has (--frames A:B[:STEP]) and which of them one process renders
// (--shard I/N: a batch scheduler's array task I of N).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace vkw::cli {

// Frame numbers A, A + STEP, ... up to B inclusive, as render tools count frames.
struct FrameRange {
    int64_t first = 0;
    int64_t last = 0;
    int64_t step = 1;
    int64_t count() const { return (last - first) / step + 1; }
    std::vector<int64_t> frames() const;
    std::string text() const;  // "A:B:STEP"
};

// The largest frame number a range may name: 10^7 frames is over four days of film at 24 fps.
inline constexpr int64_t kMaxFrameNumber = 10'000'000;

// "A:B" or "A:B:STEP" with 0 <= A <= B <= kMaxFrameNumber and 1 <= STEP; vkw::UserError naming
// the option, the value and the accepted form otherwise.
FrameRange parse_frame_range(const std::string& text);

// Task `index` of `count`: the frames whose position in the range's list is index modulo count, so
// that the tasks split any range evenly whatever its step.
struct Shard {
    uint32_t index = 0;
    uint32_t count = 1;
    std::vector<int64_t> frames_of(const FrameRange& range) const;
};

// The most tasks a sequence may be split into.
inline constexpr uint32_t kMaxShards = 100'000;

// "I/N" with 0 <= I < N <= kMaxShards; vkw::UserError otherwise.
Shard parse_shard(const std::string& text);

}  // namespace vkw::cli
