// Geometry derived from the scene description: sun angles to a direction, and the view matrix.
#include "engine/scene/scene.hpp"

#include <cmath>
#include <numbers>

#include <glm/gtc/matrix_transform.hpp>

namespace vkw {
namespace {

// sin and cos of an angle in degrees, exact at multiples of 90: reducing to [-45, 45] first
// means sin(0) = 0 and cos(0) = 1 are what gets evaluated there, instead of cos(pi/2) ~ 6e-17.
void sin_cos_deg(double deg, double& s, double& c) {
    const double quadrant = std::round(deg / 90.0);
    const double rest = (deg - 90.0 * quadrant) * (std::numbers::pi / 180.0);
    const double rs = std::sin(rest);
    const double rc = std::cos(rest);
    // ((q mod 4) + 4) mod 4 handles negative angles.
    switch (((static_cast<long long>(quadrant) % 4) + 4) % 4) {
        case 0: s = rs;  c = rc;  break;
        case 1: s = rc;  c = -rs; break;
        case 2: s = -rs; c = -rc; break;
        default: s = -rc; c = rs; break;
    }
}

}  // namespace

glm::dvec3 direction_toward_sun(double elevation_deg, double azimuth_deg) {
    double sin_el = 0.0, cos_el = 0.0, sin_az = 0.0, cos_az = 0.0;
    sin_cos_deg(elevation_deg, sin_el, cos_el);
    sin_cos_deg(azimuth_deg, sin_az, cos_az);
    return {cos_el * sin_az, sin_el, -cos_el * cos_az};
}

glm::dmat4 view_matrix(const Camera& camera) {
    const glm::dvec3 dir = glm::normalize(camera.target - camera.position);
    // Near vertical, cross(dir, +y) degenerates and the image would spin about the view
    // axis; there |dir.z| < 0.045, so -z is safely far from parallel to dir.
    const glm::dvec3 up = std::abs(dir.y) > 0.999 ? glm::dvec3(0.0, 0.0, -1.0) : glm::dvec3(0.0, 1.0, 0.0);
    return glm::lookAtRH(camera.position, camera.target, up);
}

}  // namespace vkw
