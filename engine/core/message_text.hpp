// How an error message quotes text: on one line (the CLI prints a message as it is and tests match
// it by substring), with a user's input cut to a readable length (a 50 MB string or a whole data
// URI must not come back whole).
#pragma once

#include <algorithm>
#include <cstddef>
#include <string>
#include <string_view>

namespace vkw {

// Line breaks become spaces.
inline std::string one_line(std::string text) {
    std::replace_if(
        text.begin(), text.end(), [](char c) { return c == '\n' || c == '\r'; }, ' ');
    return text;
}

// At most `max_chars` characters of `text`, then "..." and the full length when it was cut.
inline std::string shortened_input(std::string_view text, std::size_t max_chars = 40) {
    if (text.size() <= max_chars) return std::string(text);
    return std::string(text.substr(0, max_chars)) + "... (" + std::to_string(text.size()) + " characters)";
}

}  // namespace vkw
