#include "tools/reference/floor_caustics.hpp"

#include "engine/core/errors.hpp"
#include "engine/core/parallel.hpp"
#include "tools/reference/optics.hpp"
#include "tools/reference/polygon_clip.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <memory>

namespace vkw::ref {

FloorCausticMap::FloorCausticMap(const Scene& scene, const WaterSurface& surface, uint32_t texels_per_side,
                                 uint32_t cells_per_side)
    : FloorCausticMap(scene, surface, texels_per_side, cells_per_side, Tile{0.0, scene.water->half_extent, false},
                      Tile{0.0, scene.floor.half_extent, false}, scene.floor.height) {}

FloorCausticMap::FloorCausticMap(const Scene& scene, const WaterSurface& surface, uint32_t texels_per_side,
                                 uint32_t cells_per_side, double period)
    : FloorCausticMap(scene, surface, texels_per_side, cells_per_side, period, scene.floor.height) {}

FloorCausticMap::FloorCausticMap(const Scene& scene, const WaterSurface& surface, uint32_t texels_per_side,
                                 uint32_t cells_per_side, double period, double plane_y)
    : FloorCausticMap(
          scene, surface, texels_per_side, cells_per_side,
          period > 0.0 ? Tile{0.5 * period, 0.5 * period, true} : Tile{0.0, scene.water->half_extent, false},
          period > 0.0 ? Tile{0.5 * period, 0.5 * period, true} : Tile{0.0, scene.floor.half_extent, false}, plane_y) {}

FloorCausticMap::FloorCausticMap(const Scene& scene, const WaterSurface& surface, uint32_t texels_per_side,
                                 uint32_t cells_per_side, const Tile& cells, const Tile& texels, double plane_y)
    : source_(scene.source.string()),
      texels_(texels_per_side),
      centre_(texels.centre),
      half_extent_(texels.half_side),
      texel_size_(2.0 * texels.half_side / texels_per_side),
      periodic_(texels.periodic),
      irradiance_(size_t{texels_per_side} * texels_per_side, glm::dvec3(0.0)) {
    const glm::dvec3 s = scene.sun.direction;
    if (s.y >= 0.0) return;  // sun below the horizon: no caustics
    const double ior = scene.water->ior;
    const double floor_y = plane_y;
    const glm::dvec3 sigma_t = scene.medium.sigma_t();
    const double extent = cells.half_side;
    const uint32_t m = cells_per_side;
    triangles_ = 2.0 * m * m;
    // The surface's vertices and their refracted rays, one row at a time.
    struct Vertex {
        glm::dvec3 position;
        glm::dvec2 floor_hit;
        double path;
        bool valid;
    };
    auto vertex = [&](uint32_t i, uint32_t j) {
        const double x0 = cells.centre + extent * (2.0 * i - m) / m, z0 = cells.centre + extent * (2.0 * j - m) / m;
        const SurfacePoint p = surface.at_parameter(x0, z0);
        Vertex v{p.position, {}, 0.0, false};
        const auto t = refract(s, p.normal, 1.0 / ior);
        if (!t || t->y > -1e-9) return v;  // a ray that does not go down reaches no floor
        v.path = (p.position.y - floor_y) / -t->y;
        if (v.path < 0.0) return v;  // a vertex below the plane reaches none of it
        const glm::dvec3 hit = p.position + v.path * *t;
        v.floor_hit = {hit.x, hit.z};
        v.valid = true;
        return v;
    };
    std::vector<Vertex> previous(m + 1), current(m + 1);
    for (uint32_t i = 0; i <= m; ++i) previous[i] = vertex(i, 0);
    for (uint32_t j = 1; j <= m; ++j) {
        for (uint32_t i = 0; i <= m; ++i) current[i] = vertex(i, j);
        for (uint32_t i = 0; i < m; ++i) {
            const Vertex* quad[4] = {&previous[i], &previous[i + 1], &current[i + 1], &current[i]};
            for (const auto& triangle : {std::array<int, 3>{0, 1, 2}, std::array<int, 3>{0, 2, 3}}) {
                ++triangles_passed_;
                const Vertex& a = *quad[triangle[0]];
                const Vertex& b = *quad[triangle[1]];
                const Vertex& c = *quad[triangle[2]];
                if (!a.valid || !b.valid || !c.valid) continue;
                // The beam's flux through the surface triangle (docs/model.md section 4).
                glm::dvec3 normal = glm::cross(c.position - a.position, b.position - a.position);
                const double twice_area = glm::length(normal);
                if (twice_area == 0.0) continue;
                normal /= twice_area;
                if (normal.y < 0.0) normal = -normal;
                const double cos_i = -glm::dot(s, normal);
                if (cos_i <= 0.0) continue;  // faces away from the sun
                const double transmittance = 1.0 - fresnel_reflectance(cos_i, 1.0, ior);
                const double path = (a.path + b.path + c.path) / 3.0;
                const glm::dvec3 attenuation{std::exp(-sigma_t.x * path), std::exp(-sigma_t.y * path),
                                             std::exp(-sigma_t.z * path)};
                const glm::dvec3 flux = scene.sun.irradiance * (cos_i * 0.5 * twice_area * transmittance) * attenuation;
                const glm::dvec2 footprint[3] = {a.floor_hit, b.floor_hit, c.floor_hit};
                deposit(footprint, flux);
            }
        }
        std::swap(previous, current);
    }
}

// The deposits' work is the texels in their footprints' bounding boxes: about 1.5e9 for the FFT
// ocean's finer floor map and a few 1e7 for the other built-in scenes' maps. Waves short against
// the depth below them (the ocean's spectrum on a 1 mm patch) spread each beam over
// thousands of texels, and the map would take days: refused as soon as the work done, or the
// work projected from the triangles passed so far (after 256 of them, with 8 times the bound as
// the margin for a start unlike the rest), passes the bound.
void FloorCausticMap::charge_visits(double box) {
    constexpr double kMaxTexelVisits = 2e10;
    constexpr double kProjectionMargin = 8.0;
    constexpr double kProjectionStart = 256.0;
    visits_ += box;
    const double projected = visits_ * triangles_ / std::max(1.0, triangles_passed_);
    if (visits_ <= kMaxTexelVisits &&
        (triangles_passed_ < kProjectionStart || projected <= kProjectionMargin * kMaxTexelVisits))
        return;
    char text[320];
    std::snprintf(text, sizeof text,
                  "%s: water.waves: the reference's caustic map would visit about %.2g texels, each beam spreading "
                  "over %.3g of them (accepted: at most %.0e visits, waves long against the water's depth)",
                  source_.c_str(), std::max(projected, visits_), visits_ / std::max(1.0, triangles_passed_),
                  kMaxTexelVisits);
    throw UserError(text);
}

int64_t FloorCausticMap::texel_of(double coordinate) const {
    // Clamped where doubles stop counting whole texels (a beam running nearly level for 1e14 m
    // lands 1e20 texels away), and well inside int64_t.
    const double texel = std::floor((coordinate - centre_ + half_extent_) / texel_size_);
    return static_cast<int64_t>(std::clamp(texel, -kFarthestTexel, kFarthestTexel));
}

int64_t FloorCausticMap::texel_index(int64_t x, int64_t z) const {
    const int64_t n = texels_;
    if (periodic_) {
        x = ((x % n) + n) % n;
        z = ((z % n) + n) % n;
    } else if (x < 0 || z < 0 || x >= n || z >= n) {
        return -1;
    }
    return z * n + x;
}

void FloorCausticMap::deposit(const glm::dvec2 footprint[3], const glm::dvec3& flux) {
    const Polygon triangle{footprint[0], footprint[1], footprint[2]};
    const double footprint_area = area(triangle);
    const double texel_area = texel_size_ * texel_size_;
    if (footprint_area < 1e-30) {
        // A footprint collapsed to a point or a segment (a focus): all its flux lands in
        // the texel of its centroid.
        const glm::dvec2 centre = (footprint[0] + footprint[1] + footprint[2]) / 3.0;
        const int64_t index = texel_index(texel_of(centre.x), texel_of(centre.y));
        if (index >= 0) irradiance_[size_t(index)] += flux / texel_area;
        return;
    }
    const glm::dvec2 lo = glm::min(glm::min(footprint[0], footprint[1]), footprint[2]);
    const glm::dvec2 hi = glm::max(glm::max(footprint[0], footprint[1]), footprint[2]);
    // On a periodic map the texels past the tile's edge are those of the next period.
    const int64_t first = 0, last = texels_ - 1;
    const int64_t x0 = periodic_ ? texel_of(lo.x) : std::max(first, texel_of(lo.x));
    const int64_t x1 = periodic_ ? texel_of(hi.x) : std::min(last, texel_of(hi.x));
    const int64_t z0 = periodic_ ? texel_of(lo.y) : std::max(first, texel_of(lo.y));
    const int64_t z1 = periodic_ ? texel_of(hi.y) : std::min(last, texel_of(hi.y));
    if (periodic_ && std::max({-x0, x1, -z0, z1}) >= int64_t(kFarthestTexel)) {
        char text[320];
        std::snprintf(text, sizeof text,
                      "%s: water.waves: a refracted beam reaches the floor %.3g m away, beyond where the reference's "
                      "periodic caustic map places a texel (accepted: slopes that refract the sun downward)",
                      source_.c_str(), glm::length(hi));
        throw UserError(text);
    }
    charge_visits(double(x1 - x0 + 1) * double(z1 - z0 + 1));
    // Column by column: the footprint cut to the column once, then only the column's texels that
    // the cut reaches (the same clips as overlap_with_square's per texel, so the same areas bit for
    // bit; the texels left out overlap nothing). A sheared footprint's bounding box is mostly empty.
    const double origin = centre_ - half_extent_;
    for (int64_t x = x0; x <= x1; ++x) {
        const ColumnCut column = cut_to_column(triangle, origin + x * texel_size_, texel_size_);
        if (column.polygon.size < 3) continue;
        // One row more on each side: a division's rounding must not drop a row that a sliver reaches.
        const int64_t z_first = std::max(z0, texel_of(column.y_min) - 1);
        const int64_t z_last = std::min(z1, texel_of(column.y_max) + 1);
        for (int64_t z = z_first; z <= z_last; ++z) {
            const double overlap = overlap_in_column(column, origin + z * texel_size_, texel_size_);
            if (overlap > 0.0) irradiance_[size_t(texel_index(x, z))] += flux * (overlap / footprint_area / texel_area);
        }
    }
}

glm::dvec3 FloorCausticMap::irradiance(double x, double z) const {
    const int64_t index = texel_index(texel_of(x), texel_of(z));
    return index >= 0 ? irradiance_[size_t(index)] : glm::dvec3(0.0);
}

glm::dvec3 FloorCausticMap::irradiance_over_double_texels(double x, double z) const {
    const int64_t x0 = texel_of(x) & ~int64_t{1}, z0 = texel_of(z) & ~int64_t{1};
    glm::dvec3 sum(0.0);
    for (int64_t dz = 0; dz < 2; ++dz) {
        for (int64_t dx = 0; dx < 2; ++dx) {
            const int64_t index = texel_index(x0 + dx, z0 + dz);
            if (index >= 0) sum += irradiance_[size_t(index)];
        }
    }
    return 0.25 * sum;
}

glm::dvec3 FloorCausticMap::total_flux() const {
    glm::dvec3 sum(0.0);
    for (const glm::dvec3& e : irradiance_) sum += e;
    return sum * texel_size_ * texel_size_;
}

RefinedFloorCaustics refine_floor_caustics(const Scene& scene, const WaterSurface& surface, uint32_t texels_per_side,
                                           uint32_t coarse_cells_per_side, double period) {
    auto build = [&](uint32_t cells) {
        return period > 0.0 ? std::make_unique<FloorCausticMap>(scene, surface, texels_per_side, cells, period)
                            : std::make_unique<FloorCausticMap>(scene, surface, texels_per_side, cells);
    };
    // The two maps are independent: the finer one is built on a thread of its own.
    RefinedFloorCaustics refined;
    std::unique_ptr<FloorCausticMap> coarse_map;
    run_on_threads(2, [&](unsigned index) {
        if (index == 0)
            coarse_map = build(coarse_cells_per_side);
        else
            refined.map = build(2 * coarse_cells_per_side);
    });
    const FloorCausticMap& coarse = *coarse_map;
    double mean = 0.0;
    for (const glm::dvec3& e : coarse.texels()) mean += e.x + e.y + e.z;
    mean /= 3.0 * coarse.texels().size();
    double squared = 0.0, reference = 0.0;
    for (size_t k = 0; k < coarse.texels().size(); ++k) {
        const glm::dvec3 a = refined.map->texels()[k], b = coarse.texels()[k];
        if (b.x + b.y + b.z < 3e-3 * mean) continue;
        const glm::dvec3 d = a - b;
        squared += glm::dot(d, d);
        reference += glm::dot(a, a);
    }
    refined.relative_rms_change = reference > 0.0 ? std::sqrt(squared / reference) : 0.0;
    return refined;
}

}  // namespace vkw::ref
