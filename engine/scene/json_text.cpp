// JSON text to nlohmann::json with positioned, path-named errors (see json_text.hpp).
#include "engine/scene/json_text.hpp"

#include <algorithm>

#include <string>
#include <vector>

namespace vkw {
namespace {

using json = nlohmann::json;

// nlohmann's "number overflow" exception id: a number literal beyond the double range.
constexpr int kNumberOverflowId = 406;

std::string describe_position(std::string_view text, std::size_t offset) {
    const TextPosition at = text_position(text, offset);
    return "line " + std::to_string(at.line) + ", column " + std::to_string(at.column);
}

// nlohmann's what() reads "[json.exception.parse_error.101] parse error at line 1, column 2:
// syntax error while parsing ..."; its position is replaced by ours, so keep only the reason.
std::string parse_reason(const json::exception& error) {
    const std::string what = without_last_read(error.what());
    const std::size_t reason = what.find("syntax error");
    return reason == std::string::npos ? what : what.substr(reason);
}

// True when `token` is one whole string or number literal.
bool is_value_token(const std::string& token) {
    if (token.size() >= 2 && token.front() == '"' && token.back() == '"') return true;
    return !token.empty() && token.find_first_not_of("0123456789+-.eE") == std::string::npos;
}

// Byte offset to show for a parse error. `position` counts the characters read, so the last
// one read is at position - 1. When nlohmann's `last_token` is a whole string or number, its
// start is where a reader looks ("sun" after a missing comma, the 1e999); otherwise it may
// also hold earlier tokens and whitespace ("0], }"), and only position - 1 is sure.
std::size_t error_offset(std::size_t position, const std::string& last_token) {
    if (is_value_token(last_token) && position >= last_token.size()) return position - last_token.size();
    return position == 0 ? 0 : position - 1;
}

// A SAX handler that builds the document as nlohmann's own DOM parser does, but knows the
// path of the value being parsed (to name the field of a 1e999) and refuses duplicate keys.
class DocumentBuilder {
public:
    DocumentBuilder(std::string_view text, const ErrorContext& errors) : text_(text), errors_(errors) {}

    bool null() { return add(json(nullptr)); }
    bool boolean(bool value) { return add(json(value)); }
    bool number_integer(json::number_integer_t value) { return add(json(value)); }
    bool number_unsigned(json::number_unsigned_t value) { return add(json(value)); }
    bool number_float(json::number_float_t value, const json::string_t& /*literal*/) { return add(json(value)); }
    bool string(json::string_t& value) { return add(json(std::move(value))); }
    bool binary(json::binary_t& value) { return add(json(std::move(value))); }  // not produced by JSON text
    bool start_object(std::size_t /*elements*/) { return open(json::object()); }
    bool start_array(std::size_t /*elements*/) { return open(json::array()); }
    bool end_object() { return close(); }
    bool end_array() { return close(); }

    bool key(json::string_t& name) {
        Frame& frame = frames_.back();
        if (frame.node->contains(name)) {
            errors_.fail(field_path(path_through(frames_.size() - 1), name), "duplicate key",
                         "each key at most once per object");
        }
        frame.key = std::move(name);
        return true;
    }

    bool parse_error(std::size_t position, const std::string& last_token, const json::exception& error) {
        const std::size_t start = error_offset(position, last_token);
        if (error.id == kNumberOverflowId) {
            errors_.fail(path_through(frames_.size()),
                         last_token + " is not a finite number (" + describe_position(text_, start) + ")",
                         "numbers of magnitude below 1.8e308");
        }
        errors_.fail(describe_position(text_, start), "malformed JSON: " + parse_reason(error),
                     "JSON as in RFC 8259: no comments, no trailing commas");
    }

    json take() { return std::move(root_); }

private:
    struct Frame {
        json* node;       // an open object or array
        std::string key;  // for an object: the key whose value comes next
    };

    // Where the next value goes. Pointers to open containers stay valid: a container only
    // grows while it is the innermost frame, when no pointer into it is held.
    json* slot() {
        if (frames_.empty()) return &root_;
        Frame& frame = frames_.back();
        if (frame.node->is_array()) {
            frame.node->push_back(nullptr);
            return &frame.node->back();
        }
        return &(*frame.node)[frame.key];
    }

    bool add(json value) {
        *slot() = std::move(value);
        return true;
    }

    bool open(json container) {
        if (frames_.size() >= kMaxJsonNesting) {
            // The path of 64 levels of [0] is 190 characters: name where it starts and its depth.
            std::string where = path_through(frames_.size());
            if (where.size() > 60)
                where = where.substr(0, 40) + "... (" + std::to_string(frames_.size() + 1) + " levels)";
            errors_.fail(where, "nested too deeply",
                         "at most " + std::to_string(kMaxJsonNesting) + " levels of objects and arrays");
        }
        json* node = slot();
        *node = std::move(container);
        frames_.push_back({node, {}});
        return true;
    }

    bool close() {
        frames_.pop_back();
        return true;
    }

    // Field path of the slot in frame count - 1 (the value being parsed there).
    std::string path_through(std::size_t count) const {
        std::string path;
        for (std::size_t i = 0; i < count; ++i) {
            const Frame& frame = frames_[i];
            if (frame.node->is_array()) {
                // An array with an open container below it already holds that container.
                const bool child_open = i + 1 < frames_.size();
                path = element_path(path, frame.node->size() - (child_open ? 1 : 0));
            } else {
                path = field_path(path, frame.key);
            }
        }
        return path;
    }

    std::string_view text_;
    const ErrorContext& errors_;
    json root_;
    std::vector<Frame> frames_;
};

}  // namespace

std::string without_last_read(std::string message) {
    const std::string marker = "; last read: '";
    const std::size_t begin = message.find(marker);
    if (begin == std::string::npos) return message;
    // The token ends at the quote before "; expected ...", or at the message's last quote.
    std::size_t end = message.find("'; expected", begin + marker.size());
    if (end == std::string::npos) end = message.rfind('\'');
    if (end == std::string::npos || end < begin + marker.size()) return message.substr(0, begin);
    return message.erase(begin, end + 1 - begin);
}

TextPosition text_position(std::string_view text, std::size_t offset) {
    TextPosition at;
    const std::size_t end = std::min(offset, text.size());
    for (std::size_t i = 0; i < end; ++i) {
        if (text[i] == '\n') {
            ++at.line;
            at.column = 1;
        } else if ((static_cast<unsigned char>(text[i]) & 0xC0) != 0x80) {
            // UTF-8 continuation bytes (10xxxxxx) do not start a character: editors count characters.
            ++at.column;
        }
    }
    return at;
}

std::size_t json_nesting_depth(std::string_view text) {
    std::size_t depth = 0, deepest = 0;
    bool in_string = false, escaped = false;
    for (const char c : text) {
        if (in_string) {
            if (escaped) {
                escaped = false;
            } else if (c == '\\') {
                escaped = true;
            } else if (c == '"') {
                in_string = false;
            }
            continue;
        }
        if (c == '"') {
            in_string = true;
        } else if (c == '[' || c == '{') {
            deepest = std::max(deepest, ++depth);
        } else if ((c == ']' || c == '}') && depth > 0) {
            --depth;
        }
    }
    return deepest;
}

nlohmann::json parse_json_text(std::string_view text, const ErrorContext& errors) {
    if (text.find_first_not_of(" \t\r\n") == std::string_view::npos) {
        errors.fail("", "empty (no JSON value)", "a JSON object");
    }
    // A UTF-16 file (as some Windows editors save) would otherwise be "invalid literal" at line 1.
    if (text.starts_with("\xFF\xFE") || text.starts_with("\xFE\xFF")) {
        errors.fail("", "UTF-16 text (it starts with a UTF-16 byte order mark)", "UTF-8 JSON text");
    }
    DocumentBuilder builder(text, errors);
    json::sax_parse(text.begin(), text.end(), &builder);
    return builder.take();
}

}  // namespace vkw
