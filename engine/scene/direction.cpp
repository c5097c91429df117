// Unit vectors (see direction.hpp).
#include "engine/scene/direction.hpp"

#include <algorithm>
#include <cmath>

namespace vkw {

std::optional<glm::dvec3> unit_direction(const glm::dvec3& given) {
    const double largest = std::max({std::abs(given.x), std::abs(given.y), std::abs(given.z)});
    if (largest == 0.0) return std::nullopt;
    return glm::normalize(given / largest);
}

}  // namespace vkw
