// The one place scene-loading errors are worded: "<file>: <where>: <what> (accepted: <range>)",
// thrown as a one-line vkw::UserError. It also remembers which fields came from overrides,
// so that an error about such a field says which --set caused it.
#pragma once

#include <string>
#include <string_view>
#include <vector>

namespace vkw {

class ErrorContext {
public:
    explicit ErrorContext(std::string file_name);

    // Records that the field at `path` (e.g. "camera.fov_y_deg") was set by override `text`.
    void note_override(std::string path, std::string text);

    // `where` is a field path ("camera.near"; empty means the top level) or a location such
    // as "line 3, column 7". `accepted` may be empty when there is no range to state.
    [[noreturn]] void fail(std::string_view where, std::string_view what, std::string_view accepted = {}) const;

    const std::string& file_name() const { return file_name_; }

private:
    struct OverrideNote {
        std::string path;
        std::string text;
    };
    std::string file_name_;
    std::vector<OverrideNote> overrides_;
};

// Field paths as they appear in messages: "camera" + "near" -> "camera.near",
// "sun.irradiance" + 1 -> "sun.irradiance[1]".
std::string field_path(std::string_view parent, std::string_view key);
std::string element_path(std::string_view parent, std::size_t index);

}  // namespace vkw
