// The sun's irradiance on the floor under a wavy surface, without kernel bias (issue 10,
// seed 004's illumination volumes done exactly): the water surface is cut into
// triangles on an M x M parameter grid; each triangle's refracted beam carries the flux
// E_s max(0, -s.N) A T(theta_i) exp(-sigma_t l) (PHYSICS.md section 4) onto the floor,
// where its footprint is the triangle through the three refracted vertex rays' floor
// hits. Each footprint spreads its flux evenly and deposits it into the floor's texels
// by exact polygon overlap, so a texel holds the texel-averaged irradiance (the box
// filter PHYSICS.md section 5 compares against), folds and focal lines included (a
// footprint's area may tend to 0, its deposit stays finite). The map is built at M and
// 2M and the difference is the estimated error.
#pragma once

#include "engine/scene/scene.hpp"
#include "engine/water/surface.hpp"

#include <glm/glm.hpp>

#include <vector>

namespace vkw::ref {

class FloorCausticMap {
public:
    // Texels of `texel_size` metres over the floor square [-F, F]^2, F the floor's half extent.
    FloorCausticMap(const Scene& scene, const WaterSurface& surface, uint32_t texels_per_side, uint32_t cells_per_side);

    // The texel-averaged sun irradiance at floor point (x, z), W m^-2 per channel.
    glm::dvec3 irradiance(double x, double z) const;
    // Total flux that reached the floor, W per channel (for energy checks).
    glm::dvec3 total_flux() const;
    uint32_t texels_per_side() const { return texels_; }
    const std::vector<glm::dvec3>& texels() const { return irradiance_; }

private:
    void deposit(const glm::dvec2 footprint[3], const glm::dvec3& flux);
    uint32_t texels_;
    double half_extent_, texel_size_;
    std::vector<glm::dvec3> irradiance_;  // row-major, z then x
};

// Builds the map at cells and 2 cells per side and reports the relative RMS difference
// of the finer one from the coarser one over texels lit above 1e-3 of the mean.
struct RefinedFloorCaustics {
    std::unique_ptr<FloorCausticMap> map;  // the finer one
    double relative_rms_change = 0.0;
};
RefinedFloorCaustics refine_floor_caustics(const Scene& scene, const WaterSurface& surface, uint32_t texels_per_side,
                                           uint32_t coarse_cells_per_side);

}  // namespace vkw::ref
