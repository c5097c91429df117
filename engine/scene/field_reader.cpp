// Typed, range-checked reads of a JSON object with unknown-field detection (see field_reader.hpp).
#include "engine/scene/field_reader.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <limits>

#include "engine/scene/suggest.hpp"

namespace vkw {
namespace {

using json = nlohmann::json;

// Long values are cut so that a message stays a readable single line.
constexpr std::size_t kMaxShownChars = 40;

std::string shortened(std::string text) {
    if (text.size() > kMaxShownChars) text = text.substr(0, kMaxShownChars) + "...";
    return text;
}

// True for strings such as "nan", "inf" or "1e999": an override value that is not JSON
// arrives as a string, and "not a finite number" is the useful message for those.
bool names_non_finite_number(const std::string& text) {
    if (text.empty()) return false;
    char* end = nullptr;
    const double value = std::strtod(text.c_str(), &end);
    return end == text.c_str() + text.size() && !std::isfinite(value);
}

std::string vec3_accepted(const Range& range) {
    if (range.contains(-std::numeric_limits<double>::max()) && range.contains(std::numeric_limits<double>::max())) {
        return "an array of 3 finite numbers" + (range.unit.empty() ? "" : ", in " + range.unit);
    }
    return "an array of 3 numbers, each " + range.describe();
}

std::string join(const std::vector<std::string>& keys) {
    std::string out;
    for (const std::string& key : keys) out += (out.empty() ? "" : ", ") + key;
    return out;
}

}  // namespace

std::string describe_value(const json& value) {
    if (value.is_array()) {
        const char* noun = value.size() == 1 ? " element " : " elements ";
        return "array of " + std::to_string(value.size()) + noun + shortened(value.dump());
    }
    if (value.is_null()) return "null";
    return std::string(value.type_name()) + " " + shortened(value.dump());
}

FieldReader::FieldReader(const json& object, std::string path, const ErrorContext& errors)
    : object_(object), path_(std::move(path)), errors_(errors) {}

const json* FieldReader::find(std::string_view key) {
    if (std::find(known_.begin(), known_.end(), key) == known_.end()) known_.emplace_back(key);
    const auto it = object_.find(std::string(key));
    return it == object_.end() ? nullptr : &*it;
}

bool FieldReader::has(std::string_view key) { return find(key) != nullptr; }

void FieldReader::note_missing(std::string_view key, std::string accepted) {
    missing_.push_back({std::string(key), std::move(accepted)});
}

double FieldReader::to_number(const json& value, const std::string& path, const Range& range) const {
    if (value.is_number()) {
        const double number = value.get<double>();
        if (!std::isfinite(number)) errors_.fail(path, format_number(number) + " is not a finite number", range.describe());
        if (!range.contains(number)) errors_.fail(path, format_number(number) + " is out of range", range.describe());
        return number;
    }
    if (value.is_string() && names_non_finite_number(value.get_ref<const std::string&>())) {
        errors_.fail(path, describe_value(value) + " is not a finite number", range.describe());
    }
    fail_type(path, "a number", value, range.describe());
}

std::optional<double> FieldReader::optional_number(std::string_view key, const Range& range) {
    const json* value = find(key);
    if (value == nullptr) return std::nullopt;
    return to_number(*value, path_of(key), range);
}

double FieldReader::number(std::string_view key, const Range& range) {
    if (const auto value = optional_number(key, range)) return *value;
    note_missing(key, range.describe());
    return std::numeric_limits<double>::quiet_NaN();
}

double FieldReader::number(std::string_view key, const Range& range, double fallback) {
    return optional_number(key, range).value_or(fallback);
}

std::optional<glm::dvec3> FieldReader::optional_vec3(std::string_view key, const Range& range) {
    const json* value = find(key);
    if (value == nullptr) return std::nullopt;
    const std::string path = path_of(key);
    if (!value->is_array() || value->size() != 3) fail_type(path, "an array of 3 numbers", *value, vec3_accepted(range));
    glm::dvec3 result;
    for (std::size_t i = 0; i < 3; ++i) {
        result[static_cast<glm::length_t>(i)] = to_number((*value)[i], element_path(path, i), range);
    }
    return result;
}

glm::dvec3 FieldReader::vec3(std::string_view key, const Range& range) {
    if (const auto value = optional_vec3(key, range)) return *value;
    note_missing(key, vec3_accepted(range));
    return glm::dvec3(std::numeric_limits<double>::quiet_NaN());
}

glm::dvec3 FieldReader::vec3(std::string_view key, const Range& range, const glm::dvec3& fallback) {
    return optional_vec3(key, range).value_or(fallback);
}

std::optional<std::string> FieldReader::optional_string(std::string_view key) {
    const json* value = find(key);
    if (value == nullptr) return std::nullopt;
    if (!value->is_string()) fail_type(path_of(key), "a string", *value, {});
    return value->get<std::string>();
}

std::string FieldReader::string(std::string_view key, std::string fallback) {
    return optional_string(key).value_or(std::move(fallback));
}

void FieldReader::finish() {
    if (finished_) return;
    finished_ = true;
    for (const auto& item : object_.items()) {
        if (std::find(known_.begin(), known_.end(), item.key()) != known_.end()) continue;
        std::string what = "unknown field";
        if (const auto hint = closest_key(item.key(), known_)) what += " (did you mean '" + *hint + "'?)";
        errors_.fail(path_of(item.key()), what, join(known_));
    }
    if (!missing_.empty()) {
        errors_.fail(path_of(missing_.front().key), "missing required field", missing_.front().accepted);
    }
}

void FieldReader::fail(std::string_view key, std::string_view what, std::string_view accepted) const {
    errors_.fail(path_of(key), what, accepted);
}

void FieldReader::fail_type(const std::string& path, std::string_view expected, const json& value,
                            std::string_view accepted) const {
    errors_.fail(path, "expected " + std::string(expected) + ", got " + describe_value(value), accepted);
}

std::string FieldReader::path_of(std::string_view key) const {
    return key.empty() ? path_ : field_path(path_, key);
}

const json& FieldReader::empty_object() {
    static const json empty = json::object();
    return empty;
}

}  // namespace vkw
