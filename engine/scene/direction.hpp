// Unit vectors from direction vectors of any finite magnitude, as scene files give them.
#pragma once

#include <optional>

#include <glm/glm.hpp>

namespace vkw {

// `given` / |given|, or nullopt for the zero vector. Dividing by the largest component first
// keeps the length computation from overflowing (1e200 components) or underflowing (1e-200).
std::optional<glm::dvec3> unit_direction(const glm::dvec3& given);

}  // namespace vkw
