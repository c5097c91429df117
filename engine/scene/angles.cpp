// Angles in degrees (see angles.hpp).
#include "engine/scene/angles.hpp"

#include <cmath>
#include <numbers>

namespace vkw {

void sin_cos_deg(double deg, double& s, double& c) {
    // Reducing to [-45, 45] first means sin(0) = 0 and cos(0) = 1 are what gets evaluated at
    // multiples of 90, instead of cos(pi/2) ~ 6e-17.
    const double quadrant = std::round(deg / 90.0);
    const double rest = (deg - 90.0 * quadrant) * (std::numbers::pi / 180.0);
    const double rs = std::sin(rest);
    const double rc = std::cos(rest);
    // ((q mod 4) + 4) mod 4 handles negative angles.
    switch (((static_cast<long long>(quadrant) % 4) + 4) % 4) {
        case 0:
            s = rs;
            c = rc;
            break;
        case 1:
            s = rc;
            c = -rs;
            break;
        case 2:
            s = -rs;
            c = -rc;
            break;
        default:
            s = -rc;
            c = rs;
            break;
    }
}

glm::dmat3 euler_xyz_deg(const glm::dvec3& angles_deg) {
    double sx = 0.0, cx = 1.0, sy = 0.0, cy = 1.0, sz = 0.0, cz = 1.0;
    sin_cos_deg(angles_deg.x, sx, cx);
    sin_cos_deg(angles_deg.y, sy, cy);
    sin_cos_deg(angles_deg.z, sz, cz);
    // glm is column-major: each constructor line below is one column.
    const glm::dmat3 rx(1, 0, 0, 0, cx, sx, 0, -sx, cx);
    const glm::dmat3 ry(cy, 0, -sy, 0, 1, 0, sy, 0, cy);
    const glm::dmat3 rz(cz, sz, 0, -sz, cz, 0, 0, 0, 1);
    return rz * ry * rx;
}

}  // namespace vkw
