// Exact overlap of a convex polygon with an axis-aligned square, for spreading a beam's flux
// over texels or receiver patches (floor_caustics.cpp, beam_irradiance.cpp).
#pragma once

#include <glm/glm.hpp>

#include <vector>

namespace vkw::ref {

using Polygon = std::vector<glm::dvec2>;

// Sutherland-Hodgman: the part of `polygon` on the side of the axis-aligned line
// coordinate[axis] (>= or <=) bound.
Polygon clip(const Polygon& polygon, int axis, double bound, bool keep_greater);

double area(const Polygon& polygon);

// The area of `polygon` inside the square [lo, lo + size]^2.
double overlap_with_square(const Polygon& polygon, const glm::dvec2& lo, double size);

}  // namespace vkw::ref
