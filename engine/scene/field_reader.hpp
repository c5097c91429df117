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

class FieldReader {
public:
    // `object` (a JSON object) and `errors` must outlive the reader; `path` is the object's
    // own field path, empty for the top level.
    FieldReader(const nlohmann::json& object, std::string path, const ErrorContext& errors);

    std::optional<double> optional_number(std::string_view key, const Range& range);
    double number(std::string_view key, const Range& range);                   // required
    double number(std::string_view key, const Range& range, double fallback);  // optional

    // A 3-vector is an array of exactly three numbers, each within `range`.
    std::optional<glm::dvec3> optional_vec3(std::string_view key, const Range& range);
    glm::dvec3 vec3(std::string_view key, const Range& range);
    glm::dvec3 vec3(std::string_view key, const Range& range, const glm::dvec3& fallback);

    std::optional<std::string> optional_string(std::string_view key);
    std::string string(std::string_view key, std::string fallback);

    // Reads the object at `key` with `read(FieldReader&)` and finishes the child reader.
    // An absent optional section is read from an empty object, so it takes all its defaults.
    template <class Read>
    std::invoke_result_t<Read&, FieldReader&> object(std::string_view key, Presence presence, Read&& read);

    // Declares `key` valid here; true when it is present. For fields whose type decides
    // how they are read.
    bool has(std::string_view key);

    // Reports the first unknown key, then the first missing required field. Idempotent.
    void finish();

    // Fails with the field path of `key` (of this object itself when `key` is empty).
    [[noreturn]] void fail(std::string_view key, std::string_view what, std::string_view accepted = {}) const;

    std::string path_of(std::string_view key) const;

private:
    const nlohmann::json* find(std::string_view key);
    void note_missing(std::string_view key, std::string accepted);
    double to_number(const nlohmann::json& value, const std::string& path, const Range& range) const;
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
    std::vector<std::string> known_;  // every key asked for, in order: the valid keys here
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

// "string \"wide\"", "array [1,2]": a value's type and (shortened) text for messages.
std::string describe_value(const nlohmann::json& value);

}  // namespace vkw
