#include "tools/reference/polygon_clip.hpp"

#include <cmath>

namespace vkw::ref {

Polygon clip(const Polygon& polygon, int axis, double bound, bool keep_greater) {
    Polygon out;
    const size_t n = polygon.size();
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
    return out;
}

double area(const Polygon& polygon) {
    double twice = 0.0;
    for (size_t i = 0; i < polygon.size(); ++i) {
        const glm::dvec2& a = polygon[i];
        const glm::dvec2& b = polygon[(i + 1) % polygon.size()];
        twice += a.x * b.y - b.x * a.y;
    }
    return 0.5 * std::abs(twice);
}

double overlap_with_square(const Polygon& polygon, const glm::dvec2& lo, double size) {
    Polygon part = clip(polygon, 0, lo.x, true);
    part = clip(part, 0, lo.x + size, false);
    part = clip(part, 1, lo.y, true);
    part = clip(part, 1, lo.y + size, false);
    return part.size() < 3 ? 0.0 : area(part);
}

}  // namespace vkw::ref
