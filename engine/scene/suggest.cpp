// Nearest-key suggestions for unknown scene fields (see suggest.hpp).
#include "engine/scene/suggest.hpp"

#include <algorithm>
#include <cctype>

namespace vkw {
namespace {

// Lower case without '_' and '-': "fov_y_deg" and "FovYDeg" spell the same key for matching.
std::string loose(std::string_view key) {
    std::string out;
    for (const char c : key) {
        if (c != '_' && c != '-') out += static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    }
    return out;
}

// Lower scores are better matches. A prefix ("fov" of "fov_y_deg") is stronger evidence than
// two edits ("fov" is also two edits from "far"), but weaker than one.
constexpr std::size_t kMaxEdits = 2;
constexpr std::size_t kPrefixScore = 2;
constexpr std::size_t kNoMatch = 4;

std::size_t edit_score(std::size_t distance) { return distance < kMaxEdits ? distance : kMaxEdits + 1; }

// Two edits turn most short words into each other ("size" into "time"): a word of up to five
// letters may be one edit off, a longer one two.
std::size_t allowed_edits(std::size_t length) { return length <= 5 ? 1 : kMaxEdits; }

}  // namespace

std::size_t edit_distance(std::string_view a, std::string_view b) {
    // Three rows of the dynamic-programming table: the swap rule looks two rows back.
    std::vector<std::size_t> before(b.size() + 1), previous(b.size() + 1), current(b.size() + 1);
    for (std::size_t j = 0; j <= b.size(); ++j) previous[j] = j;
    for (std::size_t i = 1; i <= a.size(); ++i) {
        current[0] = i;
        for (std::size_t j = 1; j <= b.size(); ++j) {
            const std::size_t substitution = a[i - 1] == b[j - 1] ? 0 : 1;
            current[j] = std::min({previous[j] + 1, current[j - 1] + 1, previous[j - 1] + substitution});
            if (i > 1 && j > 1 && a[i - 1] == b[j - 2] && a[i - 2] == b[j - 1]) {
                current[j] = std::min(current[j], before[j - 2] + 1);
            }
        }
        std::swap(before, previous);
        std::swap(previous, current);
    }
    return previous[b.size()];
}

std::optional<std::string> closest_key(std::string_view typed, const std::vector<std::string>& valid) {
    const std::string typed_loose = loose(typed);
    std::optional<std::string> best;
    std::size_t best_score = kNoMatch;
    for (const std::string& key : valid) {
        const std::string key_loose = loose(key);
        const std::size_t distance = edit_distance(typed_loose, key_loose);
        std::size_t score = kNoMatch;
        if (distance <= allowed_edits(typed_loose.size()) && distance < typed_loose.size()) {
            score = edit_score(distance);
        }
        if (std::min(typed_loose.size(), key_loose.size()) >= 2 &&
            (key_loose.starts_with(typed_loose) || typed_loose.starts_with(key_loose))) {
            score = std::min(score, kPrefixScore);
        }
        if (score < best_score) {
            best_score = score;
            best = key;
        }
    }
    return best;
}

}  // namespace vkw
