// Flat water: P = (x0, level, z0), tangents along x and z, normal +y.
#include "engine/water/flat_surface.hpp"

namespace vkw {

FlatSurface::FlatSurface(double level) : level_(level) {}

SurfacePoint FlatSurface::at_parameter(double x0, double z0) const {
    return make_surface_point(glm::dvec3(x0, level_, z0), glm::dvec3(1.0, 0.0, 0.0), glm::dvec3(0.0, 0.0, 1.0));
}

}  // namespace vkw
