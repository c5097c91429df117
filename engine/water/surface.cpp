// The shared parts of every surface model: the normal from the tangents, and the Newton
// inversion of the horizontal displacement behind height_at.
#include "engine/water/surface.hpp"

#include <cmath>
#include <limits>

namespace vkw {

namespace {

constexpr double kNewtonTolerance = 1e-12;  // m, horizontal miss accepted as "on target"
constexpr int kNewtonMaxIterations = 50;
constexpr int kMaxStepHalvings = 40;
// |cross(dP_dv, dP_du)| is the ratio of surface area to parameter area (tangents are m/m).
// Below this the surface is squeezed to a line or a point (a cusp) and the direction of the
// cross product is rounding noise: at a Gerstner crest of steepness 1 it is about 1e-17
// and points sideways.
constexpr double kDegenerateAreaRatio = 1e-12;

// Horizontal miss of the displaced point of `parameter` from the target (x, z).
glm::dvec2 horizontal_miss(const WaterSurface& surface, const glm::dvec2& parameter, const glm::dvec2& target) {
    const SurfacePoint p = surface.at_parameter(parameter.x, parameter.y);
    return glm::dvec2(p.position.x, p.position.z) - target;
}

}  // namespace

SurfacePoint make_surface_point(const glm::dvec3& position, const glm::dvec3& dP_du, const glm::dvec3& dP_dv) {
    SurfacePoint point;
    point.position = position;
    point.dP_du = dP_du;
    point.dP_dv = dP_dv;
    const glm::dvec3 n = glm::cross(dP_dv, dP_du);
    const double length = glm::length(n);
    if (!(length > kDegenerateAreaRatio) || !std::isfinite(length)) {
        point.normal = glm::dvec3(0.0, 1.0, 0.0);
        return point;
    }
    point.normal = n / length;
    if (point.normal.y < 0.0) {
        point.normal = -point.normal;
    }
    return point;
}

WaterSurface::~WaterSurface() = default;

glm::dvec2 WaterSurface::parameter_at(double x, double z) const {
    const glm::dvec2 target(x, z);
    glm::dvec2 parameter = target;
    if (is_heightfield()) {
        return parameter;
    }
    glm::dvec2 miss = horizontal_miss(*this, parameter, target);
    for (int iteration = 0; iteration < kNewtonMaxIterations; ++iteration) {
        const double miss_length = glm::length(miss);
        if (miss_length <= kNewtonTolerance) {
            break;
        }
        // Jacobian of (x0, z0) -> (P.x, P.z): columns are the horizontal tangents.
        const SurfacePoint p = at_parameter(parameter.x, parameter.y);
        const double a = p.dP_du.x, b = p.dP_dv.x;
        const double c = p.dP_du.z, d = p.dP_dv.z;
        const double det = a * d - b * c;
        glm::dvec2 step = miss;  // fixed-point step when the Jacobian is singular
        if (std::isfinite(det) && std::abs(det) > 1e-300) {
            step = glm::dvec2(d * miss.x - b * miss.y, -c * miss.x + a * miss.y) / det;
        }
        // Damping: accept the first of step, step/2, step/4, ... that reduces the miss.
        bool improved = false;
        double scale = 1.0;
        for (int halving = 0; halving <= kMaxStepHalvings; ++halving, scale *= 0.5) {
            const glm::dvec2 candidate = parameter - scale * step;
            const glm::dvec2 candidate_miss = horizontal_miss(*this, candidate, target);
            if (glm::length(candidate_miss) < miss_length) {
                parameter = candidate;
                miss = candidate_miss;
                improved = true;
                break;
            }
        }
        if (!improved) {
            break;  // at the limit of double rounding: nothing reduces the miss any more
        }
    }
    return parameter;
}

double WaterSurface::max_slope() const { return std::numeric_limits<double>::infinity(); }

double WaterSurface::max_curvature() const { return std::numeric_limits<double>::infinity(); }

double WaterSurface::height_at(double x, double z) const {
    const glm::dvec2 parameter = parameter_at(x, z);
    return at_parameter(parameter.x, parameter.y).position.y;
}

}  // namespace vkw
