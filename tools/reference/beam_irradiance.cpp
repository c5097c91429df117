#include "tools/reference/beam_irradiance.hpp"

#include "tools/reference/optics.hpp"
#include "tools/reference/polygon_clip.hpp"

#include <algorithm>
#include <cmath>

namespace vkw::ref {

BeamIrradiance::BeamIrradiance(const Scene& scene, const WaterSurface& surface, uint32_t cells_per_side, double patch)
    : sun_direction_(scene.sun.direction),
      sun_irradiance_(scene.sun.irradiance),
      sigma_t_(scene.medium.sigma_t()),
      ior_(scene.water->ior),
      level_(scene.water->level),
      extent_(scene.water->half_extent),
      amplitude_(surface.max_amplitude()),
      patch_(patch),
      cells_(cells_per_side),
      vertices_(size_t(cells_per_side + 1) * (cells_per_side + 1)) {
    if (sun_direction_.y >= 0.0) return;  // no sun under the water
    flat_refracted_ = *refract(sun_direction_, {0.0, 1.0, 0.0}, 1.0 / ior_);
    const glm::dvec2 flat_drift = glm::dvec2(flat_refracted_.x, flat_refracted_.z) / -flat_refracted_.y;
    for (uint32_t j = 0; j <= cells_; ++j) {
        for (uint32_t i = 0; i <= cells_; ++i) {
            const double x0 = extent_ * (2.0 * i - cells_) / cells_, z0 = extent_ * (2.0 * j - cells_) / cells_;
            const SurfacePoint p = surface.at_parameter(x0, z0);
            Vertex& v = vertices_[size_t(j) * (cells_ + 1) + i];
            v.position = p.position;
            const auto t = refract(sun_direction_, p.normal, 1.0 / ior_);
            if (!t || t->y > -1e-9) continue;  // a ray that does not go down reaches nothing below
            v.refracted = *t;
            v.valid = true;
            const glm::dvec2 drift = glm::dvec2(t->x, t->z) / -t->y;
            spread_ = std::max(spread_, glm::length(drift - flat_drift));
        }
    }
}

BeamIrradiance::Patch BeamIrradiance::square_patch(const glm::dvec3& normal, double side) {
    // Any two perpendicular axes of the receiver's tangent plane.
    const glm::dvec3 axis_u = glm::normalize(
        glm::cross(std::abs(normal.y) < 0.9 ? glm::dvec3(0.0, 1.0, 0.0) : glm::dvec3(1.0, 0.0, 0.0), normal));
    return {side * axis_u, side * glm::cross(normal, axis_u)};
}

glm::dvec3 BeamIrradiance::irradiance(const glm::dvec3& point, const glm::dvec3& normal,
                                      const Visibility& visible) const {
    return irradiance(point, normal, visible, patch_);
}

glm::dvec3 BeamIrradiance::irradiance(const glm::dvec3& point, const glm::dvec3& normal, const Visibility& visible,
                                      double patch) const {
    return patch > 0.0 ? irradiance(point, normal, visible, square_patch(normal, patch))
                       : irradiance(point, normal, visible, Patch{});
}

glm::dvec3 BeamIrradiance::irradiance(const glm::dvec3& point, const glm::dvec3& normal, const Visibility& visible,
                                      const Patch& patch) const {
    glm::dvec3 total(0.0);
    if (sun_direction_.y >= 0.0 || point.y >= level_ + amplitude_) return total;
    // The patch's coordinates: a point q of the tangent plane is point + s u + t v, (s, t) from
    // the inverse of the 2 x 2 Gram system; the patch is (s, t) in [-1/2, 1/2]^2.
    const double uu = glm::dot(patch.u, patch.u), uv = glm::dot(patch.u, patch.v), vv = glm::dot(patch.v, patch.v);
    const double gram = uu * vv - uv * uv;
    const double patch_area = std::sqrt(std::max(0.0, gram));
    const bool averaged = patch_area > 0.0;
    auto patch_coordinates = [&](const glm::dvec3& q) {
        const double qu = glm::dot(q - point, patch.u), qv = glm::dot(q - point, patch.v);
        return glm::dvec2((vv * qu - uv * qv) / gram, (uu * qv - uv * qu) / gram);
    };
    // The flat beam through the point enters the mean level here; every beam that reaches the
    // patch entered within `radius` of it (its drift differs by at most spread_ per metre of
    // depth; the surface moves by at most the amplitude vertically and, displaced, sideways).
    const double depth = level_ + amplitude_ - point.y;
    const glm::dvec3 flat_entry = point - ((level_ - point.y) / -flat_refracted_.y) * flat_refracted_;
    const double cell = 2.0 * extent_ / cells_;
    const double radius =
        depth * spread_ +
        amplitude_ * (1.0 + glm::length(glm::dvec2(flat_refracted_.x, flat_refracted_.z)) / -flat_refracted_.y) +
        2.0 * cell + glm::length(patch.u) + glm::length(patch.v);
    auto index_of = [&](double coordinate) { return static_cast<int64_t>(std::floor((coordinate + extent_) / cell)); };
    const int64_t i0 = std::max<int64_t>(0, index_of(flat_entry.x - radius));
    const int64_t i1 = std::min<int64_t>(cells_ - 1, index_of(flat_entry.x + radius));
    const int64_t j0 = std::max<int64_t>(0, index_of(flat_entry.z - radius));
    const int64_t j1 = std::min<int64_t>(cells_ - 1, index_of(flat_entry.z + radius));
    for (int64_t j = j0; j <= j1; ++j) {
        for (int64_t i = i0; i <= i1; ++i) {
            const Vertex* quad[4] = {&vertex(uint32_t(i), uint32_t(j)), &vertex(uint32_t(i + 1), uint32_t(j)),
                                     &vertex(uint32_t(i + 1), uint32_t(j + 1)), &vertex(uint32_t(i), uint32_t(j + 1))};
            for (const auto& corners : {std::array<int, 3>{0, 1, 2}, std::array<int, 3>{0, 2, 3}}) {
                const Vertex* v[3] = {quad[corners[0]], quad[corners[1]], quad[corners[2]]};
                if (!v[0]->valid || !v[1]->valid || !v[2]->valid) continue;
                // The footprint: where the three vertex rays meet the receiver's plane.
                glm::dvec3 footprint[3];
                double along[3];
                bool reaches = true;
                for (int k = 0; k < 3 && reaches; ++k) {
                    const double facing = glm::dot(v[k]->refracted, normal);
                    reaches = facing < 0.0;  // the beam arrives on the lit side
                    along[k] = reaches ? glm::dot(point - v[k]->position, normal) / facing : 0.0;
                    reaches = reaches && along[k] > 0.0;
                    footprint[k] = v[k]->position + along[k] * v[k]->refracted;
                }
                if (!reaches) continue;
                const double twice_area =
                    glm::dot(glm::cross(footprint[1] - footprint[0], footprint[2] - footprint[0]), normal);
                // The beam's flux through the surface triangle (docs/model.md section 4).
                glm::dvec3 surface_normal =
                    glm::cross(v[2]->position - v[0]->position, v[1]->position - v[0]->position);
                const double twice_surface_area = glm::length(surface_normal);
                if (twice_surface_area == 0.0) continue;
                surface_normal /= twice_surface_area;
                if (surface_normal.y < 0.0) surface_normal = -surface_normal;
                const double cos_i = -glm::dot(sun_direction_, surface_normal);
                if (cos_i <= 0.0) continue;  // faces away from the sun
                // The share of the footprint that falls on the patch (or whether it holds the point).
                double share = 0.0;
                double weights[3] = {1.0 / 3.0, 1.0 / 3.0, 1.0 / 3.0};  // where the beam is followed back
                if (averaged) {
                    const glm::dvec2 st[3] = {patch_coordinates(footprint[0]), patch_coordinates(footprint[1]),
                                              patch_coordinates(footprint[2])};
                    const glm::dvec2 lo = glm::min(st[0], glm::min(st[1], st[2]));
                    const glm::dvec2 hi = glm::max(st[0], glm::max(st[1], st[2]));
                    if (lo.x > 0.5 || lo.y > 0.5 || hi.x < -0.5 || hi.y < -0.5) continue;  // misses the patch
                    const Polygon footprint_st{st[0], st[1], st[2]};
                    const double footprint_area = 0.5 * std::abs(twice_area);
                    if (footprint_area < 1e-30) {
                        // A footprint collapsed to a focus: all its flux lands where its centroid is.
                        const glm::dvec2 centre = (footprint_st[0] + footprint_st[1] + footprint_st[2]) / 3.0;
                        share = std::abs(centre.x) <= 0.5 && std::abs(centre.y) <= 0.5 ? 1.0 / patch_area : 0.0;
                    } else {
                        // The overlap in (s, t) is a fraction of the patch; times its area, of the footprint.
                        share = overlap_with_square(footprint_st, glm::dvec2(-0.5), 1.0) / footprint_area;
                    }
                } else {
                    if (std::abs(twice_area) < 1e-300) continue;
                    for (int k = 0; k < 3; ++k) {
                        const glm::dvec3& a = footprint[(k + 1) % 3];
                        const glm::dvec3& b = footprint[(k + 2) % 3];
                        weights[k] = glm::dot(glm::cross(a - point, b - point), normal) / twice_area;
                    }
                    if (weights[0] < 0.0 || weights[1] < 0.0 || weights[2] < 0.0) continue;  // outside this beam
                    share = 1.0 / (0.5 * std::abs(twice_area));
                }
                if (share == 0.0) continue;
                const double path = weights[0] * along[0] + weights[1] * along[1] + weights[2] * along[2];
                const glm::dvec3 direction = glm::normalize(
                    weights[0] * v[0]->refracted + weights[1] * v[1]->refracted + weights[2] * v[2]->refracted);
                const glm::dvec3 entry =
                    weights[0] * v[0]->position + weights[1] * v[1]->position + weights[2] * v[2]->position;
                if (!visible(point, direction, path, entry)) continue;
                const double transmittance = 1.0 - fresnel_reflectance(cos_i, 1.0, ior_);
                const glm::dvec3 flux = sun_irradiance_ * (cos_i * 0.5 * twice_surface_area * transmittance);
                const glm::dvec3 attenuation{std::exp(-sigma_t_.x * path), std::exp(-sigma_t_.y * path),
                                             std::exp(-sigma_t_.z * path)};
                total += flux * attenuation * share;
            }
        }
    }
    return total;
}

}  // namespace vkw::ref
