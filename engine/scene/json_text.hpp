// Parsing scene JSON text with errors a user can act on: syntax errors with line and column,
// numbers too large for a double (1e999), and duplicate keys (a copied block whose key was not
// renamed silently loses one of the two values in a plain parse), and nesting deep enough to
// overflow the stack of later recursive code.
#pragma once

#include <cstddef>
#include <string>
#include <string_view>

#include <nlohmann/json.hpp>

#include "engine/scene/error_context.hpp"

namespace vkw {

// 1-based line and column (in UTF-8 characters) of the byte at `offset` in `text`;
// an offset past the end means the end of the text.
struct TextPosition {
    std::size_t line = 1;
    std::size_t column = 1;
};
TextPosition text_position(std::string_view text, std::size_t offset);

// nlohmann's syntax error messages quote the token they last read, which can be a whole long
// string (a 300-character description, a 7 KB data URI) or bytes that are not text: the message
// without "; last read: '...'" (the line and column already point there).
std::string without_last_read(std::string message);

// The deepest nesting of objects and arrays that a scene or an override value may have: enough
// for any scene, and far from what overflows the stack of nlohmann::json's recursive printing.
inline constexpr std::size_t kMaxJsonNesting = 64;

// The deepest nesting of objects and arrays in `text`, brackets inside strings not counted; one
// pass, no recursion (for text that has not been parsed yet).
std::size_t json_nesting_depth(std::string_view text);

// Parses `text` as one JSON value. Throws UserError through `errors` on any problem.
nlohmann::json parse_json_text(std::string_view text, const ErrorContext& errors);

}  // namespace vkw
