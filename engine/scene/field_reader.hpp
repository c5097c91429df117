// FieldReader: the one mechanism that reads a JSON object of the scene schema. Each read
// names a key, checks the type and the Range, and records the key as valid at this level;
// finish() then reports any key that no read asked for as an unknown field (with a "did you
// mean" hint drawn from the recorded keys) and any missing required field. New schema
// sections are written as functions over a FieldReader (see camera_json.cpp).
//
// Usage rule: read every field first, call finish(), and only then check relations between
// fields. finish() reports unknown fields before missing ones, because a misspelt key
// ("camra") explains the missing one ("camera") and is the better message. A missing
// required field yields a placeholder (NaN, or a default-constructed section) until then.
#pragma once

#include <array>
#include <cstdint>
#include <initializer_list>
#include <optional>
#include <string>
#include <string_view>
#include <type_traits>
#include <vector>

#include <glm/glm.hpp>
#include <nlohmann/json.hpp>

#include "engine/scene/error_context.hpp"
#include "engine/scene/range.hpp"

namespace vkw {

enum class Presence { required, optional };

// The largest integer field value: every integer up to 2^53 - 1 is held exactly by a double
// (and by any JSON reader). Seeds use the whole range.
inline constexpr double kMaxExactInteger = 9007199254740991.0;

// One accepted name of an enumerated string field and the value it stands for.
template <class T>
struct Named {
    std::string_view name;
    T value;
};

// "one of plane, box, sphere": the accepted values of an enumerated field.
std::string one_of(const std::vector<std::string_view>& names);

class FieldReader {
public:
    // `object` (a JSON object) and `errors` must outlive the reader; `path` is the object's
    // own field path, empty for the top level.
    FieldReader(const nlohmann::json& object, std::string path, const ErrorContext& errors);

    std::optional<double> optional_number(std::string_view key, const Range& range);
    double number(std::string_view key, const Range& range);                   // required
    double number(std::string_view key, const Range& range, double fallback);  // optional
    // A number in `range`, or the string `word` in its place (nullopt then): a field such as a
    // water's extent, which may be "infinite".
    std::optional<double> number_or_word(std::string_view key, const Range& range, std::string_view word,
                                         double fallback);

    // A 3-vector is an array of exactly three numbers, each within `range`.
    std::optional<glm::dvec3> optional_vec3(std::string_view key, const Range& range);
    glm::dvec3 vec3(std::string_view key, const Range& range);
    glm::dvec3 vec3(std::string_view key, const Range& range, const glm::dvec3& fallback);

    std::optional<glm::dvec2> optional_vec2(std::string_view key, const Range& range);
    glm::dvec2 vec2(std::string_view key, const Range& range);

    // An integer is a number without fractional part ("256" or "256.0"). Keep `range` within
    // +-2^53, where doubles hold every integer exactly.
    std::optional<int64_t> optional_integer(std::string_view key, const Range& range);
    int64_t integer(std::string_view key, const Range& range);                    // required
    int64_t integer(std::string_view key, const Range& range, int64_t fallback);  // optional

    std::optional<bool> optional_boolean(std::string_view key);
    bool boolean(std::string_view key, bool fallback);

    std::optional<std::string> optional_string(std::string_view key);
    std::string string(std::string_view key, std::string fallback);

    // A string naming one of `options`; an unknown name is refused with a "did you mean" hint.
    template <class T, std::size_t N>
    std::optional<T> optional_choice(std::string_view key, const std::array<Named<T>, N>& options);
    template <class T, std::size_t N>
    T choice(std::string_view key, const std::array<Named<T>, N>& options, T fallback);
    // The same over names alone: the index of the name given.
    std::optional<std::size_t> optional_choice_index(std::string_view key, const std::vector<std::string_view>& names);
    // Required: nullopt (and a missing field reported by finish()) when absent.
    template <class T, std::size_t N>
    std::optional<T> required_choice(std::string_view key, const std::array<Named<T>, N>& options);

    // Reads the object at `key` with `read(FieldReader&)` and finishes the child reader.
    // An absent optional section is read from an empty object, so it takes all its defaults.
    template <class Read>
    std::invoke_result_t<Read&, FieldReader&> object(std::string_view key, Presence presence, Read&& read);

    // An array of objects, each read with `read(FieldReader&)` (whose path is "key[i]") and
    // finished. Absent: empty.
    template <class Read>
    std::vector<std::invoke_result_t<Read&, FieldReader&>> objects(std::string_view key, Read&& read);

    // Declares `key` valid here; true when it is present. For fields whose type decides
    // how they are read.
    bool has(std::string_view key);

    // Declares keys valid without reading them. An object whose kind field ("type", "model")
    // decides its other fields declares the fields of every kind when the kind is missing, so
    // that finish() reports a misspelt kind field rather than the fields it would have allowed.
    void declare(std::initializer_list<std::string_view> keys);
    // Keys that belong to another setting of this object (a different model): still unknown
    // here, but refused with `fix` (what to change) instead of a spelling hint.
    void belong_elsewhere(std::initializer_list<std::string_view> keys, std::string fix);

    // Reports the first unknown key, then the first missing required field. Idempotent.
    void finish();

    // Fails with the field path of `key` (of this object itself when `key` is empty).
    [[noreturn]] void fail(std::string_view key, std::string_view what, std::string_view accepted = {}) const;

    std::string path_of(std::string_view key) const;

private:
    const nlohmann::json* find(std::string_view key);
    void note_missing(std::string_view key, std::string accepted);
    double to_number(const nlohmann::json& value, const std::string& path, const Range& range,
                     const std::string& accepted) const;
    void to_numbers(const nlohmann::json& value, const std::string& path, const Range& range, double* out,
                    std::size_t count) const;

    [[noreturn]] void fail_type(const std::string& path, std::string_view expected, const nlohmann::json& value,
                                std::string_view accepted) const;
    static const nlohmann::json& empty_object();

    struct Missing {
        std::string key;
        std::string accepted;
    };

    const nlohmann::json& object_;
    std::string path_;
    const ErrorContext& errors_;
    std::vector<std::string> known_;                              // every key asked for, in order: the valid keys here
    std::vector<std::pair<std::string, std::string>> elsewhere_;  // key, the fix that makes it valid
    std::vector<Missing> missing_;
    bool finished_ = false;
};

template <class Read>
std::invoke_result_t<Read&, FieldReader&> FieldReader::object(std::string_view key, Presence presence, Read&& read) {
    using Result = std::invoke_result_t<Read&, FieldReader&>;
    const nlohmann::json* value = find(key);
    if (value == nullptr) {
        if (presence == Presence::required) {
            note_missing(key, "an object");
            return Result{};
        }
        value = &empty_object();
    } else if (!value->is_object()) {
        fail_type(path_of(key), "an object", *value, {});
    }
    FieldReader child(*value, path_of(key), errors_);
    Result result = read(child);
    child.finish();
    return result;
}

template <class T, std::size_t N>
std::optional<T> FieldReader::optional_choice(std::string_view key, const std::array<Named<T>, N>& options) {
    std::vector<std::string_view> names;
    for (const Named<T>& option : options) names.push_back(option.name);
    const std::optional<std::size_t> index = optional_choice_index(key, names);
    if (!index) return std::nullopt;
    return options[*index].value;
}

template <class T, std::size_t N>
T FieldReader::choice(std::string_view key, const std::array<Named<T>, N>& options, T fallback) {
    return optional_choice(key, options).value_or(fallback);
}

template <class T, std::size_t N>
std::optional<T> FieldReader::required_choice(std::string_view key, const std::array<Named<T>, N>& options) {
    const std::optional<T> value = optional_choice(key, options);
    if (!value) {
        std::vector<std::string_view> names;
        for (const Named<T>& option : options) names.push_back(option.name);
        note_missing(key, one_of(names));
    }
    return value;
}

template <class Read>
std::vector<std::invoke_result_t<Read&, FieldReader&>> FieldReader::objects(std::string_view key, Read&& read) {
    std::vector<std::invoke_result_t<Read&, FieldReader&>> results;
    const nlohmann::json* value = find(key);
    if (value == nullptr) return results;
    if (!value->is_array()) fail_type(path_of(key), "an array of objects", *value, {});
    for (std::size_t i = 0; i < value->size(); ++i) {
        const nlohmann::json& element = (*value)[i];
        const std::string path = element_path(path_of(key), i);
        if (!element.is_object()) fail_type(path, "an object", element, {});
        FieldReader child(element, path, errors_);
        results.push_back(read(child));
        child.finish();
    }
    return results;
}

// "string \"wide\"", "array [1,2]": a value's type and (shortened) text for messages.
std::string describe_value(const nlohmann::json& value);

}  // namespace vkw
