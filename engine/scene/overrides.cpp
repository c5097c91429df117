// "key.path=value" overrides applied to scene JSON (see overrides.hpp).
#include "engine/scene/overrides.hpp"

#include <string_view>

#include "engine/scene/field_reader.hpp"

namespace vkw {
namespace {

using json = nlohmann::json;

constexpr std::string_view kSyntax = "key.path=value, e.g. camera.fov_y_deg=75 or sun.irradiance=[2,2,2]";

std::string_view trimmed(std::string_view text) {
    const std::size_t first = text.find_first_not_of(" \t");
    if (first == std::string_view::npos) return {};
    return text.substr(first, text.find_last_not_of(" \t") - first + 1);
}

std::vector<std::string> split_key(std::string_view key) {
    std::vector<std::string> parts;
    std::size_t start = 0;
    while (true) {
        const std::size_t dot = key.find('.', start);
        parts.emplace_back(key.substr(start, dot == std::string_view::npos ? std::string_view::npos : dot - start));
        if (dot == std::string_view::npos) return parts;
        start = dot + 1;
    }
}

json parse_value(std::string_view text) {
    // accept() also refuses 1e999, which then reaches validation as the string "1e999"
    // and is reported there as not a finite number.
    if (json::accept(text)) return json::parse(text);
    return json(std::string(text));
}

void apply_one(json& root, const std::string& text, ErrorContext& errors) {
    const std::string where = "override '" + text + "'";
    const std::size_t equals = text.find('=');
    if (equals == std::string::npos) errors.fail(where, "no '=' in the override", kSyntax);
    const std::vector<std::string> keys = split_key(trimmed(std::string_view(text).substr(0, equals)));
    for (const std::string& key : keys) {
        if (key.empty()) errors.fail(where, "empty field name in the key path", kSyntax);
    }
    json value = parse_value(trimmed(std::string_view(text).substr(equals + 1)));

    json* node = &root;
    std::string path;
    for (std::size_t i = 0; i + 1 < keys.size(); ++i) {
        path = field_path(path, keys[i]);
        json& child = (*node)[keys[i]];  // creates a null member when absent
        if (child.is_null()) child = json::object();
        if (!child.is_object()) {
            errors.fail(path, where + " sets a field inside a value that is not an object: " + describe_value(child),
                        "overrides of whole values, e.g. sun.irradiance=[2,2,2]");
        }
        node = &child;
    }
    path = field_path(path, keys.back());
    if (value.is_null()) {
        if (node->erase(keys.back()) == 0) errors.fail(path, where + " removes a field that the scene does not have");
    } else {
        (*node)[keys.back()] = std::move(value);
    }
    errors.note_override(path, text);
}

}  // namespace

void apply_overrides(json& root, const std::vector<std::string>& overrides, ErrorContext& errors) {
    if (!root.is_object()) return;
    for (const std::string& text : overrides) apply_one(root, text, errors);
}

}  // namespace vkw
