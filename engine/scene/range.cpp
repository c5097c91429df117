// Range checks and their wording (see range.hpp).
#include "engine/scene/range.hpp"

#include <charconv>
#include <cmath>

namespace vkw {

Range Range::any(std::string unit) { return Range{.unit = std::move(unit)}; }

Range Range::closed(double lo, double hi, std::string unit) {
    return Range{.min = lo, .max = hi, .unit = std::move(unit)};
}

Range Range::open(double lo, double hi, std::string unit) {
    return Range{.min = lo, .max = hi, .min_inclusive = false, .max_inclusive = false, .unit = std::move(unit)};
}

Range Range::at_least(double lo, std::string unit) { return Range{.min = lo, .unit = std::move(unit)}; }

Range Range::above(double lo, std::string unit) {
    return Range{.min = lo, .min_inclusive = false, .unit = std::move(unit)};
}

Range Range::length() { return closed(-kMaxSceneLength, kMaxSceneLength, "m"); }

Range Range::positive_length() {
    return Range{.min = 0.0, .max = kMaxSceneLength, .min_inclusive = false, .unit = "m"};
}

Range Range::nonnegative_length() { return closed(0.0, kMaxSceneLength, "m"); }

Range Range::radiometric(std::string unit) { return closed(0.0, kMaxRadiometric, std::move(unit)); }

bool Range::contains(double value) const {
    if (!std::isfinite(value)) return false;
    const bool above_min = min_inclusive ? value >= min : value > min;
    const bool below_max = max_inclusive ? value <= max : value < max;
    return above_min && below_max;
}

std::string Range::describe() const {
    const bool has_min = std::isfinite(min);
    const bool has_max = std::isfinite(max);
    std::string text;
    if (has_min && has_max) {
        text = format_number(min) + (min_inclusive ? " <= " : " < ") + "value" + (max_inclusive ? " <= " : " < ") +
               format_number(max);
    } else if (has_min) {
        text = std::string("value ") + (min_inclusive ? ">= " : "> ") + format_number(min);
    } else if (has_max) {
        text = std::string("value ") + (max_inclusive ? "<= " : "< ") + format_number(max);
    } else {
        return unit.empty() ? "any finite number" : "any finite number, in " + unit;
    }
    return unit.empty() ? text : text + " " + unit;
}

std::string format_number(double value) {
    char buffer[32];
    const auto result = std::to_chars(buffer, buffer + sizeof buffer, value);
    return std::string(buffer, result.ptr);
}

std::string format_vec3(const glm::dvec3& value) {
    return "[" + format_number(value.x) + ", " + format_number(value.y) + ", " + format_number(value.z) + "]";
}

}  // namespace vkw
