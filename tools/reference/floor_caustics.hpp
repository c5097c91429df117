// The sun's irradiance on the floor under a wavy surface, without kernel bias
// (Tipprasert 2006's illumination volumes done exactly): the water surface is cut into
// triangles on an M x M parameter grid; each triangle's refracted beam carries the flux
// E_s max(0, -s.N) A T(theta_i) exp(-sigma_t l) (docs/model.md section 4) onto the floor,
// where its footprint is the triangle through the three refracted vertex rays' floor
// hits. Each footprint spreads its flux evenly and deposits it into the floor's texels
// by exact polygon overlap, so a texel holds the texel-averaged irradiance (the box
// filter docs/model.md section 5 compares against), folds and focal lines included (a
// footprint's area may tend to 0, its deposit stays finite). The map is built at M and
// 2M and the difference is the estimated error.
//
// A periodic surface (the FFT ocean, period L in x and z) gives a floor irradiance with the
// same period, away from the edges of the water's extent: the map then covers one period,
// [0, L)^2, from the surface cells of one period, and footprints that cross the tile's edge
// wrap around. Floor points whose beams may come from beyond the water's extent (within the
// beams' sideways drift of the edge) still read the periodic value: the caller states that.
#pragma once

#include "engine/scene/scene.hpp"
#include "engine/water/surface.hpp"

#include <glm/glm.hpp>

#include <string>
#include <vector>

namespace vkw::ref {

class FloorCausticMap {
public:
    // Texels over the floor square [-F, F]^2, F the floor's half extent, from surface cells
    // over the water's extent.
    FloorCausticMap(const Scene& scene, const WaterSurface& surface, uint32_t texels_per_side, uint32_t cells_per_side);
    // Texels over one period [0, period)^2, from surface cells over the same square; the
    // surface must be periodic with `period` in x0 and z0.
    FloorCausticMap(const Scene& scene, const WaterSurface& surface, uint32_t texels_per_side, uint32_t cells_per_side,
                    double period);
    // The irradiance on the horizontal plane y = plane_y instead of the floor (the sun inside
    // the water at a depth, for the in-scatter), over one period (period > 0) or over the
    // floor's square (period 0). Every surface vertex must lie above the plane (plane_y at or
    // below the lowest trough); a vertex below it reaches no point of the plane.
    FloorCausticMap(const Scene& scene, const WaterSurface& surface, uint32_t texels_per_side, uint32_t cells_per_side,
                    double period, double plane_y);

    // The texel-averaged sun irradiance at floor point (x, z), W m^-2 per channel.
    glm::dvec3 irradiance(double x, double z) const;
    // The same averaged over the aligned 2 x 2 block of texels around (x, z): what a map of
    // half as many texels per side would hold there (the reference's estimate of its texels'
    // error). The map's texels per side must be even.
    glm::dvec3 irradiance_over_double_texels(double x, double z) const;
    // Total flux that reached the floor, W per channel (for energy checks).
    glm::dvec3 total_flux() const;
    uint32_t texels_per_side() const { return texels_; }
    double texel_size() const { return texel_size_; }  // m
    const std::vector<glm::dvec3>& texels() const { return irradiance_; }

    // The floor map's period, or 0 when it covers the whole floor.
    double period() const { return periodic_ ? 2.0 * half_extent_ : 0.0; }

private:
    // A square of surface cells and of floor texels, both centred on `centre` in x and z.
    struct Tile {
        double centre, half_side;
        bool periodic;
    };
    FloorCausticMap(const Scene& scene, const WaterSurface& surface, uint32_t texels_per_side, uint32_t cells_per_side,
                    const Tile& cells, const Tile& texels, double plane_y);
    void deposit(const glm::dvec2 footprint[3], const glm::dvec3& flux);
    // Counts a deposit's work (the texels of its footprint's bounding box) and refuses, naming
    // the waves, a map whose work done or projected passes a bound.
    void charge_visits(double box_texels);
    static constexpr double kFarthestTexel = 0x1p52;
    int64_t texel_of(double coordinate) const;
    // The texel (x, z) in the row-major array, wrapped on a periodic map; -1 outside the map.
    int64_t texel_index(int64_t x, int64_t z) const;
    std::string source_;  // the scene file, for the refusal
    double triangles_ = 0.0, triangles_passed_ = 0.0, visits_ = 0.0;
    uint32_t texels_;
    double centre_, half_extent_, texel_size_;
    bool periodic_;
    std::vector<glm::dvec3> irradiance_;  // row-major, z then x
};

// Builds the map at cells and 2 cells per side and reports the relative RMS difference
// of the finer one from the coarser one over texels lit above 1e-3 of the mean.
struct RefinedFloorCaustics {
    std::unique_ptr<FloorCausticMap> map;  // the finer one
    double relative_rms_change = 0.0;
};
// period > 0: the periodic map of one period (FloorCausticMap's second constructor).
RefinedFloorCaustics refine_floor_caustics(const Scene& scene, const WaterSurface& surface, uint32_t texels_per_side,
                                           uint32_t coarse_cells_per_side, double period = 0.0);

}  // namespace vkw::ref
