// The in-scatter of the sun's refracted beams under a wavy surface (godrays in the
// reference). docs/model.md section 6 integrates sigma_s p(cos alpha) E_perp(z) exp(-sigma_t u)
// along a view ray with the flat surface's beam, E_perp(z) = E_perp0 exp(-sigma_t z / cos t).
// Under waves the sun's irradiance inside the water varies sideways as well: at depth z it is
// the beam-mapped caustic irradiance E_h on the horizontal plane at that depth, the same exact
// beam mapping as the floor's (floor_caustics.hpp), built on planes at `levels` depths from
// just below the lowest trough down to the floor.
//
// Along a ray the in-scatter is summed over short segments: each segment's flat closed form
// (section 6, from the segment's start, attenuated to the ray's origin) times the modulation
// m = E_h(x, z) / E_h,flat(z) at its midpoint, per channel, linear in depth between the planes.
// Flat water gives m = 1 and the segments add up to the closed form.
// Approximations (stated in the manifest): the beams' own directions are replaced by the flat
// refracted direction t (E_perp taken as E_h / cos(theta_t), the phase function at t); the
// modulation is linear in depth between planes and, above the top plane (within the wave
// amplitude of the mean level), that of the top plane.
#pragma once

#include "engine/scene/scene.hpp"
#include "engine/water/surface.hpp"
#include "tools/reference/floor_caustics.hpp"

#include <glm/glm.hpp>

#include <memory>
#include <vector>

namespace vkw::ref {

class CausticInScatter {
public:
    struct Settings {
        uint32_t levels = 16;            // planes from the lowest trough to the floor
        uint32_t texels_per_side = 512;  // per plane's map
        uint32_t cells_per_side = 512;   // surface cells per side of each map
        double period = 0.0;             // > 0: periodic maps of one period (the FFT ocean)
    };
    // `amplitude`: the surface's bound on |h| (the top plane lies that far below the level).
    CausticInScatter(const Scene& scene, const WaterSurface& surface, double amplitude, const Settings& settings);

    // m per channel at a point in the water (1 where the flat irradiance is 0).
    glm::dvec3 modulation(const glm::dvec3& point) const;

    // The radiance arriving at `origin` along the unit `direction` in the water over `length`,
    // with `behind` at the far end: behind exp(-sigma_t length) plus the modulated in-scatter
    // (that term alone also in `in_scatter`, when given).
    glm::dvec3 segment_radiance(const glm::dvec3& origin, const glm::dvec3& direction, double length,
                                const glm::dvec3& behind, glm::dvec3* in_scatter = nullptr) const;

    double segment_length() const { return segment_length_; }
    const std::vector<double>& plane_depths() const { return depths_; }

private:
    glm::dvec3 flat_horizontal_irradiance(double depth) const;

    const Scene& scene_;
    double level_ = 0.0;
    glm::dvec3 refracted_sun_{0.0, -1.0, 0.0};
    glm::dvec3 e_perp0_{0.0};
    bool sun_up_ = false;
    std::vector<double> depths_;    // below the mean level, increasing
    std::vector<glm::dvec3> flat_;  // E_h,flat at each plane's depth
    std::vector<std::unique_ptr<FloorCausticMap>> maps_;
    double segment_length_ = 0.0;
};

}  // namespace vkw::ref
