// The floor's albedo pattern (FloorPlane::albedo_at, scene.hpp).
#include "engine/scene/scene.hpp"

#include <cmath>

namespace vkw {

glm::dvec3 FloorPlane::albedo_at(double x, double z) const {
    if (!tiles) return albedo;
    // Distance to the nearest tile edge, a multiple of the side; floor(v + 0.5) rounds as the
    // shader does (GLSL's round() may go either way at .5).
    const double side = tiles->side;
    const auto from_edge = [side](double v) { return std::abs(v - side * std::floor(v / side + 0.5)); };
    const double half_grout = 0.5 * tiles->grout;
    return from_edge(x) < half_grout || from_edge(z) < half_grout ? tiles->grout_albedo : albedo;
}

}  // namespace vkw
