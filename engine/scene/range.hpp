// The accepted interval of a numeric scene field, and how it is worded in error messages
// ("1 < value < 179 degrees", "value >= 0 W m^-2"). Non-finite values are never accepted.
#pragma once

#include <limits>
#include <string>

#include <glm/glm.hpp>

namespace vkw {

// Lengths: fp32 resolves 1/2^24 of a coordinate, 6 mm at 1e5 m, the finest the GPU's world
// positions can place a wave of a few centimetres' amplitude; areas and volumes of such lengths
// (1e10, 1e15) stay far from fp32's 3.4e38.
inline constexpr double kMaxSceneLength = 1e5;
// Radiances and irradiances: each value itself an fp32 with 8 orders of headroom for the factors
// one term multiplies it by (focusing, phase function, 1 / pixel area); products of several can
// still overflow, which the final image's scan refuses.
inline constexpr double kMaxRadiometric = 1e30;
// Extinction coefficients: a millimetre of water at 1e6 1/m transmits exp(-1000), nothing a float
// holds; sigma_s times a radiance stays within fp32 (1e36).
inline constexpr double kMaxCoefficient = 1e6;

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

    // The scene's physical quantities within what both renderers hold in 32-bit floats
    // (scenes/README.md "Limits"):
    static Range length();                       // a coordinate or height: |v| <= kMaxSceneLength m
    static Range positive_length();              // a size: 0 < v <= kMaxSceneLength m
    static Range nonnegative_length();           // 0 <= v <= kMaxSceneLength m
    static Range radiometric(std::string unit);  // a radiance or irradiance: 0 <= v <= kMaxRadiometric

    bool contains(double value) const;
    std::string describe() const;
};

// Shortest text that reads back as the same double ("0.05", "1e-07", "inf").
std::string format_number(double value);
// "[0, 1.2, 4]"
std::string format_vec3(const glm::dvec3& value);

}  // namespace vkw
