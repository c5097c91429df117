// The sun's irradiance at any receiver point under a wavy surface, from the same
// exact beams as floor_caustics.hpp (Tipprasert 2006's illumination volumes): the surface is cut
// into triangles on an M x M parameter grid; each triangle's refracted beam carries the flux
// E_s max(0, -s.N) A T(theta_i) (docs/model.md section 4) and meets the receiver's tangent
// plane in a footprint triangle through the three refracted vertex rays. A point inside a
// footprint receives flux / footprint area, attenuated by exp(-sigma_t l) along the beam and
// shadowed by whatever the caller's visibility test finds between the point and the surface
// (and above it). The irradiance is averaged over a square patch of the receiver's tangent
// plane centred on the point, by exact polygon overlap as the floor map averages over its
// texels (a point on a focal line would be singular, an integrable spike whose peak moves
// with the triangulation); patch 0 evaluates at the point itself.
// Only the triangles whose beams can reach the point are visited: those around the flat
// surface's beam through it, within the spread that the surface's slopes give the beams.
#pragma once

#include "engine/scene/scene.hpp"
#include "engine/water/surface.hpp"

#include <glm/glm.hpp>

#include <functional>
#include <vector>

namespace vkw::ref {

class BeamIrradiance {
public:
    // (point, beam direction t, path length in the water, entry point on the surface):
    // whether the sunlight of that beam reaches the point.
    using Visibility = std::function<bool(const glm::dvec3&, const glm::dvec3&, double, const glm::dvec3&)>;

    // patch: side of the averaging square, m (0: at the point).
    BeamIrradiance(const Scene& scene, const WaterSurface& surface, uint32_t cells_per_side, double patch);

    // W m^-2 per channel on the receiver's plane (normal facing the light's side).
    glm::dvec3 irradiance(const glm::dvec3& point, const glm::dvec3& normal, const Visibility& visible) const;
    // The same averaged over a square patch of another side (the reference's estimate of its
    // patch's error compares against twice the side; 0: at the point).
    glm::dvec3 irradiance(const glm::dvec3& point, const glm::dvec3& normal, const Visibility& visible,
                          double patch) const;
    // A parallelogram of the receiver's tangent plane centred on the point: point + s u + t v,
    // s and t in [-1/2, 1/2] (a share of a pixel's footprint; u = v = 0: at the point).
    struct Patch {
        glm::dvec3 u{0.0}, v{0.0};
    };
    glm::dvec3 irradiance(const glm::dvec3& point, const glm::dvec3& normal, const Visibility& visible,
                          const Patch& patch) const;
    static Patch square_patch(const glm::dvec3& normal, double side);
    double patch() const { return patch_; }

private:
    struct Vertex {
        glm::dvec3 position;
        glm::dvec3 refracted;  // unit, downward; valid only if `valid`
        bool valid = false;
    };
    const Vertex& vertex(uint32_t i, uint32_t j) const { return vertices_[size_t(j) * (cells_ + 1) + i]; }

    glm::dvec3 sun_direction_, sun_irradiance_, sigma_t_, flat_refracted_;
    double ior_ = 1.0, level_ = 0.0, extent_ = 0.0, amplitude_ = 0.0, patch_ = 0.0;
    double spread_ = 0.0;  // the most any beam's horizontal drift per metre of depth differs from the flat beam's
    uint32_t cells_ = 0;
    std::vector<Vertex> vertices_;  // (cells + 1)^2, row-major in z0 then x0
};

}  // namespace vkw::ref
