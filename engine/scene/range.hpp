// The accepted interval of a numeric scene field, and how it is worded in error messages
// ("1 < value < 179 degrees", "value >= 0 W m^-2"). Non-finite values are never accepted.
#pragma once

#include <limits>
#include <string>

#include <glm/glm.hpp>

namespace vkw {

struct Range {
    double min = -std::numeric_limits<double>::infinity();
    double max = std::numeric_limits<double>::infinity();
    bool min_inclusive = true;
    bool max_inclusive = true;
    std::string unit;  // appended to the wording; empty for dimensionless values

    static Range any(std::string unit = {});                           // any finite value
    static Range closed(double lo, double hi, std::string unit = {});  // lo <= v <= hi
    static Range open(double lo, double hi, std::string unit = {});    // lo < v < hi
    static Range at_least(double lo, std::string unit = {});           // v >= lo
    static Range above(double lo, std::string unit = {});              // v > lo

    bool contains(double value) const;
    std::string describe() const;
};

// Shortest text that reads back as the same double ("0.05", "1e-07", "inf").
std::string format_number(double value);
// "[0, 1.2, 4]"
std::string format_vec3(const glm::dvec3& value);

}  // namespace vkw
