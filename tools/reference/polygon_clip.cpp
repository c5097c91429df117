#include "tools/reference/polygon_clip.hpp"

#include "engine/core/errors.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <string>

namespace vkw::ref {
namespace {

constexpr size_t kMaxClipped = FixedPolygon::kMaxVertices;

// Sutherland-Hodgman for either polygon type (Polygon or FixedPolygon), same arithmetic.
template <typename In, typename Out>
void clip_into(const In& polygon, size_t n, int axis, double bound, bool keep_greater, Out& out) {
    for (size_t i = 0; i < n; ++i) {
        const glm::dvec2& a = polygon[i];
        const glm::dvec2& b = polygon[(i + 1) % n];
        const bool a_in = keep_greater ? a[axis] >= bound : a[axis] <= bound;
        const bool b_in = keep_greater ? b[axis] >= bound : b[axis] <= bound;
        if (a_in) out.push_back(a);
        if (a_in != b_in) {
            const double t = (bound - a[axis]) / (b[axis] - a[axis]);
            out.push_back(a + t * (b - a));
        }
    }
}

template <typename P>
double area_of(const P& polygon, size_t n) {
    double twice = 0.0;
    for (size_t i = 0; i < n; ++i) {
        const glm::dvec2& a = polygon[i];
        const glm::dvec2& b = polygon[(i + 1) % n];
        twice += a.x * b.y - b.x * a.y;
    }
    return 0.5 * std::abs(twice);
}

}  // namespace

Polygon clip(const Polygon& polygon, int axis, double bound, bool keep_greater) {
    Polygon out;
    clip_into(polygon, polygon.size(), axis, bound, keep_greater, out);
    return out;
}

double area(const Polygon& polygon) { return area_of(polygon, polygon.size()); }

ColumnCut cut_to_column(const Polygon& polygon, double x_lo, double size) {
    if (polygon.size() + 4 > kMaxClipped) {
        throw InternalError("overlap_with_square: " + std::to_string(polygon.size()) + " vertices; at most " +
                            std::to_string(kMaxClipped - 4) + " fit the fixed clip buffers");
    }
    FixedPolygon a;
    clip_into(polygon, polygon.size(), 0, x_lo, true, a);
    ColumnCut cut;
    const FixedPolygon& b = cut.polygon;
    clip_into(a, a.size, 0, x_lo + size, false, cut.polygon);
    if (b.size > 0) {
        cut.y_min = cut.y_max = b[0].y;
        for (size_t i = 1; i < b.size; ++i) {
            cut.y_min = std::min(cut.y_min, b[i].y);
            cut.y_max = std::max(cut.y_max, b[i].y);
        }
    }
    return cut;
}

double overlap_in_column(const ColumnCut& column, double y_lo, double size) {
    FixedPolygon a, b;
    clip_into(column.polygon, column.polygon.size, 1, y_lo, true, a);
    clip_into(a, a.size, 1, y_lo + size, false, b);
    return b.size < 3 ? 0.0 : area_of(b, b.size);
}

double overlap_with_square(const Polygon& polygon, const glm::dvec2& lo, double size) {
    return overlap_in_column(cut_to_column(polygon, lo.x, size), lo.y, size);
}

}  // namespace vkw::ref
