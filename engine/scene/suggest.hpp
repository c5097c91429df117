// "Did you mean ...?" for unknown scene fields: the closest valid key, if any is close.
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace vkw {

// Edit distance counting insertions, deletions, substitutions and swaps of adjacent characters
// (optimal string alignment), so the common typo "naer" is one edit from "near".
std::size_t edit_distance(std::string_view a, std::string_view b);

// The key in `valid` that `typed` most likely meant: edit distance <= 2 (and less than the
// typed length, so "ab" is not "near"), or one a prefix of the other once case and underscores
// are ignored ("fovy" -> "fov_y_deg", "fov" -> "fov_y_deg"). Best first: fewest edits up to
// one, then a prefix, then two edits; ties go to the earlier key in `valid`.
std::optional<std::string> closest_key(std::string_view typed, const std::vector<std::string>& valid);

}  // namespace vkw
