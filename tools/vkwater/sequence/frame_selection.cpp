#include "tools/vkwater/sequence/frame_selection.hpp"

#include "engine/core/errors.hpp"

#include <charconv>

namespace vkw::cli {
namespace {

// A whole decimal number in [0, max] filling `text`, or nothing.
bool parse_count(std::string_view text, int64_t max, int64_t& value) {
    if (text.empty()) return false;
    const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
    return error == std::errc() && end == text.data() + text.size() && value >= 0 && value <= max;
}

}  // namespace

std::vector<int64_t> FrameRange::frames() const {
    std::vector<int64_t> list;
    for (int64_t frame = first; frame <= last; frame += step) list.push_back(frame);
    return list;
}

std::string FrameRange::text() const {
    return std::to_string(first) + ":" + std::to_string(last) + ":" + std::to_string(step);
}

FrameRange parse_frame_range(const std::string& text) {
    const std::string accepted =
        " (accepted: A:B or A:B:STEP, frames A to B inclusive, 0 <= A <= B <= " + std::to_string(kMaxFrameNumber) +
        ", STEP >= 1)";
    const size_t colon = text.find(':');
    const size_t second = colon == std::string::npos ? std::string::npos : text.find(':', colon + 1);
    FrameRange range;
    const std::string_view view(text);
    const bool parsed =
        colon != std::string::npos && parse_count(view.substr(0, colon), kMaxFrameNumber, range.first) &&
        parse_count(view.substr(colon + 1, second == std::string::npos ? std::string::npos : second - colon - 1),
                    kMaxFrameNumber, range.last) &&
        (second == std::string::npos || parse_count(view.substr(second + 1), kMaxFrameNumber, range.step));
    if (!parsed) throw UserError("--frames '" + text + "': not a frame range" + accepted);
    if (range.last < range.first) {
        throw UserError("--frames '" + text + "': the last frame " + std::to_string(range.last) +
                        " is before the first " + std::to_string(range.first) + accepted);
    }
    if (range.step < 1) throw UserError("--frames '" + text + "': a step of 0" + accepted);
    return range;
}

std::vector<int64_t> Shard::frames_of(const FrameRange& range) const {
    std::vector<int64_t> mine;
    for (int64_t position = index; position < range.count(); position += count) {
        mine.push_back(range.first + position * range.step);
    }
    return mine;
}

Shard parse_shard(const std::string& text) {
    const size_t slash = text.find('/');
    int64_t index = -1;
    int64_t count = 0;
    const std::string_view view(text);
    if (slash == std::string::npos || !parse_count(view.substr(0, slash), kMaxShards, index) ||
        !parse_count(view.substr(slash + 1), kMaxShards, count) || count < 1 || index >= count) {
        throw UserError("--shard '" + text + "': not a task of an array (accepted: I/N, task I of N, 0 <= I < N <= " +
                        std::to_string(kMaxShards) + ")");
    }
    return Shard{static_cast<uint32_t>(index), static_cast<uint32_t>(count)};
}

}  // namespace vkw::cli
