// Exact overlap of a convex polygon with an axis-aligned square, for spreading a beam's flux
// over texels or receiver patches (floor_caustics.cpp, beam_irradiance.cpp).
#pragma once

#include <glm/glm.hpp>

#include <array>
#include <cstddef>
#include <vector>

namespace vkw::ref {

using Polygon = std::vector<glm::dvec2>;

// Sutherland-Hodgman: the part of `polygon` on the side of the axis-aligned line
// coordinate[axis] (>= or <=) bound.
Polygon clip(const Polygon& polygon, int axis, double bound, bool keep_greater);

double area(const Polygon& polygon);

// The area of `polygon` inside the square [lo, lo + size]^2.
double overlap_with_square(const Polygon& polygon, const glm::dvec2& lo, double size);

// A convex polygon of at most kMaxVertices vertices in a fixed array: clipped by the four sides of
// a square it gains at most one vertex per side, so the clips below (called millions of times by
// the caustic maps) allocate nothing.
struct FixedPolygon {
    static constexpr size_t kMaxVertices = 16;
    std::array<glm::dvec2, kMaxVertices> vertices;
    size_t size = 0;
    void push_back(const glm::dvec2& v) { vertices[size++] = v; }
    const glm::dvec2& operator[](size_t i) const { return vertices[i]; }
};

// overlap_with_square in two halves, for a caller that takes many squares of one column: the
// polygon cut to the column x in [x_lo, x_lo + size] once (the first two of its four clips), then
// the area of that cut in each square of the column (the last two). The areas are the same, bit
// for bit, as overlap_with_square's, which is made of these two.
struct ColumnCut {
    FixedPolygon polygon;
    double y_min = 0.0, y_max = 0.0;  // the cut's extent in y (meaningful when polygon.size >= 3)
};
ColumnCut cut_to_column(const Polygon& polygon, double x_lo, double size);
double overlap_in_column(const ColumnCut& column, double y_lo, double size);

}  // namespace vkw::ref
