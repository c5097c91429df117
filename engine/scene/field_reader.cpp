// Typed, range-checked reads of a JSON object with unknown-field detection (see field_reader.hpp).
#include "engine/scene/field_reader.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdlib>
#include <limits>

#include "engine/scene/suggest.hpp"

namespace vkw {
namespace {

using json = nlohmann::json;

// Long values are cut so that a message stays a readable single line.
constexpr std::size_t kMaxShownChars = 40;

// A value as JSON text for a message: a string that is not UTF-8 (a --set value can hold any
// bytes) shows U+FFFD where its bad bytes were, instead of making dump() throw.
std::string dumped(const json& value) { return value.dump(-1, ' ', false, json::error_handler_t::replace); }

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

std::string array_accepted(const Range& range, std::size_t count) {
    const std::string numbers = "an array of " + std::to_string(count);
    if (range.contains(-std::numeric_limits<double>::max()) && range.contains(std::numeric_limits<double>::max())) {
        return numbers + " finite numbers" + (range.unit.empty() ? "" : ", in " + range.unit);
    }
    return numbers + " numbers, each " + range.describe();
}

std::string integer_accepted(const Range& range) { return "an integer, " + range.describe(); }

std::string join(const std::vector<std::string>& keys) {
    std::string out;
    for (const std::string& key : keys) out += (out.empty() ? "" : ", ") + key;
    return out;
}

}  // namespace

std::string one_of(const std::vector<std::string_view>& names) {
    std::string out = "one of ";
    for (std::size_t i = 0; i < names.size(); ++i) out += (i == 0 ? "" : ", ") + std::string(names[i]);
    return out;
}

std::string describe_value(const json& value) {
    if (value.is_array()) {
        const char* noun = value.size() == 1 ? " element " : " elements ";
        return "array of " + std::to_string(value.size()) + noun + shortened(dumped(value));
    }
    if (value.is_null()) return "null";
    return std::string(value.type_name()) + " " + shortened(dumped(value));
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

double FieldReader::to_number(const json& value, const std::string& path, const Range& range,
                              const std::string& accepted) const {
    if (value.is_number()) {
        const double number = value.get<double>();
        if (!std::isfinite(number)) errors_.fail(path, format_number(number) + " is not a finite number", accepted);
        if (!range.contains(number)) errors_.fail(path, format_number(number) + " is out of range", accepted);
        return number;
    }
    if (value.is_string() && names_non_finite_number(value.get_ref<const std::string&>())) {
        errors_.fail(path, describe_value(value) + " is not a finite number", accepted);
    }
    fail_type(path, "a number", value, accepted);
}

void FieldReader::to_numbers(const json& value, const std::string& path, const Range& range, double* out,
                             std::size_t count) const {
    const std::string expected = "an array of " + std::to_string(count) + " numbers";
    if (!value.is_array() || value.size() != count) fail_type(path, expected, value, array_accepted(range, count));
    for (std::size_t i = 0; i < count; ++i) {
        out[i] = to_number(value[i], element_path(path, i), range, range.describe());
    }
}

std::optional<double> FieldReader::optional_number(std::string_view key, const Range& range) {
    const json* value = find(key);
    if (value == nullptr) return std::nullopt;
    return to_number(*value, path_of(key), range, range.describe());
}

double FieldReader::number(std::string_view key, const Range& range) {
    if (const auto value = optional_number(key, range)) return *value;
    note_missing(key, range.describe());
    return std::numeric_limits<double>::quiet_NaN();
}

double FieldReader::number(std::string_view key, const Range& range, double fallback) {
    return optional_number(key, range).value_or(fallback);
}

std::optional<double> FieldReader::number_or_word(std::string_view key, const Range& range, std::string_view word,
                                                  double fallback) {
    const json* value = find(key);
    if (value == nullptr) return fallback;
    const std::string accepted = range.describe() + ", or \"" + std::string(word) + "\"";
    if (value->is_string() && value->get<std::string>() == word) return std::nullopt;
    if (value->is_string()) fail_type(path_of(key), "a number or \"" + std::string(word) + "\"", *value, accepted);
    return to_number(*value, path_of(key), range, accepted);
}

std::optional<glm::dvec3> FieldReader::optional_vec3(std::string_view key, const Range& range) {
    const json* value = find(key);
    if (value == nullptr) return std::nullopt;
    std::array<double, 3> numbers{};
    to_numbers(*value, path_of(key), range, numbers.data(), numbers.size());
    return glm::dvec3(numbers[0], numbers[1], numbers[2]);
}

glm::dvec3 FieldReader::vec3(std::string_view key, const Range& range) {
    if (const auto value = optional_vec3(key, range)) return *value;
    note_missing(key, array_accepted(range, 3));
    return glm::dvec3(std::numeric_limits<double>::quiet_NaN());
}

glm::dvec3 FieldReader::vec3(std::string_view key, const Range& range, const glm::dvec3& fallback) {
    return optional_vec3(key, range).value_or(fallback);
}

std::optional<glm::dvec2> FieldReader::optional_vec2(std::string_view key, const Range& range) {
    const json* value = find(key);
    if (value == nullptr) return std::nullopt;
    std::array<double, 2> numbers{};
    to_numbers(*value, path_of(key), range, numbers.data(), numbers.size());
    return glm::dvec2(numbers[0], numbers[1]);
}

glm::dvec2 FieldReader::vec2(std::string_view key, const Range& range) {
    if (const auto value = optional_vec2(key, range)) return *value;
    note_missing(key, array_accepted(range, 2));
    return glm::dvec2(std::numeric_limits<double>::quiet_NaN());
}

std::optional<int64_t> FieldReader::optional_integer(std::string_view key, const Range& range) {
    const json* value = find(key);
    if (value == nullptr) return std::nullopt;
    const std::string path = path_of(key);
    const std::string accepted = integer_accepted(range);
    const double number = to_number(*value, path, range, accepted);
    if (number != std::floor(number)) errors_.fail(path, format_number(number) + " is not an integer", accepted);
    return static_cast<int64_t>(number);
}

int64_t FieldReader::integer(std::string_view key, const Range& range) {
    if (const auto value = optional_integer(key, range)) return *value;
    note_missing(key, integer_accepted(range));
    return 0;
}

int64_t FieldReader::integer(std::string_view key, const Range& range, int64_t fallback) {
    return optional_integer(key, range).value_or(fallback);
}

std::optional<bool> FieldReader::optional_boolean(std::string_view key) {
    const json* value = find(key);
    if (value == nullptr) return std::nullopt;
    if (!value->is_boolean()) fail_type(path_of(key), "true or false", *value, {});
    return value->get<bool>();
}

bool FieldReader::boolean(std::string_view key, bool fallback) { return optional_boolean(key).value_or(fallback); }

std::optional<std::string> FieldReader::optional_string(std::string_view key) {
    const json* value = find(key);
    if (value == nullptr) return std::nullopt;
    if (!value->is_string()) fail_type(path_of(key), "a string", *value, {});
    return value->get<std::string>();
}

std::string FieldReader::string(std::string_view key, std::string fallback) {
    return optional_string(key).value_or(std::move(fallback));
}

std::optional<std::size_t> FieldReader::optional_choice_index(std::string_view key,
                                                              const std::vector<std::string_view>& names) {
    const json* value = find(key);
    if (value == nullptr) return std::nullopt;
    const std::string path = path_of(key);
    if (!value->is_string()) fail_type(path, "a string", *value, one_of(names));
    const std::string& text = value->get_ref<const std::string&>();
    const auto it = std::find(names.begin(), names.end(), text);
    if (it != names.end()) return static_cast<std::size_t>(it - names.begin());
    std::string what = "unknown value " + shortened(dumped(*value));
    const std::vector<std::string> valid(names.begin(), names.end());
    if (const auto hint = closest_key(text, valid)) what += " (did you mean '" + *hint + "'?)";
    errors_.fail(path, what, one_of(names));
}

void FieldReader::declare(std::initializer_list<std::string_view> keys) {
    for (const std::string_view key : keys) find(key);
}

void FieldReader::belong_elsewhere(std::initializer_list<std::string_view> keys, std::string fix) {
    for (const std::string_view key : keys) elsewhere_.emplace_back(std::string(key), fix);
}

void FieldReader::finish() {
    if (finished_) return;
    finished_ = true;
    for (const auto& item : object_.items()) {
        if (std::find(known_.begin(), known_.end(), item.key()) != known_.end()) continue;
        std::string what = "unknown field";
        const auto other = std::find_if(elsewhere_.begin(), elsewhere_.end(),
                                        [&](const auto& entry) { return entry.first == item.key(); });
        if (other != elsewhere_.end()) {
            what = "not a field of this model (" + other->second + ")";
        } else if (const auto hint = closest_key(item.key(), known_)) {
            what += " (did you mean '" + *hint + "'?)";
        }
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

std::string FieldReader::path_of(std::string_view key) const { return key.empty() ? path_ : field_path(path_, key); }

const json& FieldReader::empty_object() {
    static const json empty = json::object();
    return empty;
}

}  // namespace vkw
