#include "tools/reference/polygon_clip.hpp"

#include "engine/core/errors.hpp"

#include <array>
#include <cmath>
#include <string>

namespace vkw::ref {
namespace {

// A convex polygon clipped by the four sides of a square gains at most one vertex per side:
// the overlap of a polygon of up to kMaxClipped - 4 vertices fits in a fixed array, so
// overlap_with_square (called millions of times by the caustic maps) allocates nothing.
constexpr size_t kMaxClipped = 16;
struct FixedPolygon {
    std::array<glm::dvec2, kMaxClipped> vertices;
    size_t size = 0;
    void push_back(const glm::dvec2& v) { vertices[size++] = v; }
    const glm::dvec2& operator[](size_t i) const { return vertices[i]; }
};

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

double overlap_with_square(const Polygon& polygon, const glm::dvec2& lo, double size) {
    if (polygon.size() + 4 > kMaxClipped) {
        throw InternalError("overlap_with_square: " + std::to_string(polygon.size()) + " vertices; at most " +
                            std::to_string(kMaxClipped - 4) + " fit the fixed clip buffers");
    }
    FixedPolygon a, b;
    clip_into(polygon, polygon.size(), 0, lo.x, true, a);
    clip_into(a, a.size, 0, lo.x + size, false, b);
    a.size = 0;
    clip_into(b, b.size, 1, lo.y, true, a);
    b.size = 0;
    clip_into(a, a.size, 1, lo.y + size, false, b);
    return b.size < 3 ? 0.0 : area_of(b, b.size);
}

}  // namespace vkw::ref
