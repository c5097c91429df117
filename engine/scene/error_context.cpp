// Wording of scene-loading errors (see error_context.hpp).
#include "engine/scene/error_context.hpp"

#include <algorithm>

#include "engine/core/errors.hpp"
#include "engine/core/message_text.hpp"

namespace vkw {
namespace {

// True when one path lies inside the other ("sun" and "sun.direction", not "sun" and "sunset"):
// an error on a section can be caused by an override of one of its fields, and vice versa.
bool paths_overlap(std::string_view a, std::string_view b) {
    if (a.size() > b.size()) std::swap(a, b);
    if (!b.starts_with(a)) return false;
    return a.size() == b.size() || b[a.size()] == '.' || b[a.size()] == '[';
}

}  // namespace

ErrorContext::ErrorContext(std::string file_name) : file_name_(std::move(file_name)) {}

void ErrorContext::note_override(std::string path, std::string text) {
    overrides_.push_back({std::move(path), std::move(text)});
}

void ErrorContext::fail(std::string_view where, std::string_view what, std::string_view accepted) const {
    std::string message =
        file_name_ + ": " + std::string(where.empty() ? "top level" : where) + ": " + std::string(what);
    if (!accepted.empty()) message += " (accepted: " + std::string(accepted) + ")";
    // The latest override wins in the JSON, so it is the one to blame.
    const auto note = std::find_if(overrides_.rbegin(), overrides_.rend(), [&](const OverrideNote& n) {
        return !where.empty() && paths_overlap(n.path, where);
    });
    if (note != overrides_.rend()) message += " [from override '" + shortened_input(note->text, 40) + "']";
    throw UserError(one_line(std::move(message)));
}

std::string field_path(std::string_view parent, std::string_view key) {
    // A key can be any string (an unknown key of 5000 characters came back whole): cut it.
    const std::string shown = shortened_input(key, 40);
    if (parent.empty()) return shown;
    return std::string(parent) + "." + shown;
}

std::string element_path(std::string_view parent, std::size_t index) {
    return std::string(parent) + "[" + std::to_string(index) + "]";
}

}  // namespace vkw
