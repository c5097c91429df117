// "key.path=value" overrides applied to scene JSON (see overrides.hpp).
#include "engine/scene/overrides.hpp"

#include <charconv>
#include <optional>
#include <string_view>
#include <vector>

#include "engine/core/message_text.hpp"
#include "engine/scene/field_reader.hpp"
#include "engine/scene/json_text.hpp"

namespace vkw {
namespace {

using json = nlohmann::json;

constexpr std::string_view kSyntax =
    "key.path=value, e.g. camera.fov_y_deg=75, sun.irradiance=[2,2,2] or receivers[0].radius=0.5";

// One step of a key path: a field name, or an array index ("[2]").
struct Step {
    std::string key;
    std::optional<std::size_t> index;
};

std::string_view trimmed(std::string_view text) {
    const std::size_t first = text.find_first_not_of(" \t");
    if (first == std::string_view::npos) return {};
    return text.substr(first, text.find_last_not_of(" \t") - first + 1);
}

// "water.waves.components[1].amplitude" -> water, waves, components, [1], amplitude.
// Empty optional on a syntax error.
std::optional<std::vector<Step>> split_key(std::string_view key) {
    std::vector<Step> steps;
    std::size_t start = 0;
    while (true) {
        const std::size_t dot = key.find('.', start);
        std::string_view part = key.substr(start, dot == std::string_view::npos ? std::string_view::npos : dot - start);
        const std::size_t bracket = part.find('[');
        const std::string_view name = part.substr(0, bracket);
        if (name.empty()) return std::nullopt;
        steps.push_back({std::string(name), std::nullopt});
        part.remove_prefix(name.size());
        while (!part.empty()) {
            const std::size_t close = part.find(']');
            std::size_t index = 0;
            if (part[0] != '[' || close == std::string_view::npos || close == 1) return std::nullopt;
            const auto [end, error] = std::from_chars(part.data() + 1, part.data() + close, index);
            if (error != std::errc() || end != part.data() + close) return std::nullopt;
            steps.push_back({"", index});
            part.remove_prefix(close + 1);
        }
        if (dot == std::string_view::npos) return steps;
        start = dot + 1;
    }
}

json parse_value(std::string_view text, const std::string& where, const ErrorContext& errors) {
    // Bounded as scene files are: 10^5 nested arrays would overflow the stack of the code that
    // later prints the value.
    if (json_nesting_depth(text) > kMaxJsonNesting) {
        errors.fail(where, "the value is nested too deeply",
                    "at most " + std::to_string(kMaxJsonNesting) + " levels of objects and arrays");
    }
    // accept() also refuses 1e999, which then reaches validation as the string "1e999"
    // and is reported there as not a finite number.
    if (json::accept(text)) return json::parse(text);
    return json(std::string(text));
}

std::string step_path(const std::string& parent, const Step& step) {
    return step.index ? element_path(parent, *step.index) : field_path(parent, step.key);
}

void apply_one(json& root, const std::string& text, ErrorContext& errors) {
    const std::string where = "override '" + shortened_input(text, 80) + "'";
    const std::size_t equals = text.find('=');
    if (equals == std::string::npos) errors.fail(where, "no '=' in the override", kSyntax);
    const auto steps = split_key(trimmed(std::string_view(text).substr(0, equals)));
    if (!steps) errors.fail(where, "empty field name or malformed [index] in the key path", kSyntax);
    json value = parse_value(trimmed(std::string_view(text).substr(equals + 1)), where, errors);

    json* node = &root;
    std::string path;
    for (std::size_t i = 0; i < steps->size(); ++i) {
        const Step& step = (*steps)[i];
        const bool last = i + 1 == steps->size();
        if (step.index) {
            // Arrays are indexed, never grown: the element must exist.
            if (!node->is_array()) {
                errors.fail(path, where + " indexes a value that is not an array: " + describe_value(*node),
                            "[index] only after an array field");
            }
            if (*step.index >= node->size()) {
                errors.fail(
                    step_path(path, step),
                    where + " indexes past the end of an array of " + std::to_string(node->size()) + " elements",
                    "an index below " + std::to_string(node->size()));
            }
        } else if (!node->is_object()) {
            errors.fail(path, where + " sets a field inside a value that is not an object: " + describe_value(*node),
                        "overrides of whole values, e.g. sun.irradiance=[2,2,2]");
        }
        path = step_path(path, step);
        if (last) break;
        json& child = step.index ? (*node)[*step.index] : (*node)[step.key];  // creates a null member when absent
        if (child.is_null()) child = json::object();
        node = &child;
    }
    const Step& step = steps->back();
    if (!value.is_null()) {
        (step.index ? (*node)[*step.index] : (*node)[step.key]) = std::move(value);
    } else if (step.index) {
        node->erase(*step.index);
    } else if (node->erase(step.key) == 0) {
        errors.fail(path, where + " removes a field that the scene does not have");
    }
    errors.note_override(path, text);
}

}  // namespace

void apply_overrides(json& root, const std::vector<std::string>& overrides, ErrorContext& errors) {
    if (!root.is_object()) return;
    for (const std::string& text : overrides) apply_one(root, text, errors);
}

}  // namespace vkw
