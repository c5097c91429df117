// Trigonometry of angles in degrees, exact at multiples of 90 degrees: the scene file states
// angles in degrees, and an overhead sun or a quarter-turned box must come out exact.
#pragma once

#include <glm/glm.hpp>

namespace vkw {

// sin and cos of `deg` degrees; exactly 0 and +-1 at multiples of 90.
void sin_cos_deg(double deg, double& s, double& c);

// Rotation by XYZ Euler angles in degrees: about x first, then y, then z, all about the fixed
// world axes, i.e. R = Rz(z) Ry(y) Rx(x).
glm::dmat3 euler_xyz_deg(const glm::dvec3& angles_deg);

}  // namespace vkw
