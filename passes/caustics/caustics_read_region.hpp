// Which texels of the light-space caustic map a frame can read, so that the photon pass can leave
// out every photon whose kernel reaches none of them: the image is bit-identical with and without
// the culling, since every texel that is read gets every photon that touches it.
//
// A texel is read where a receiver point under the water projects to it (caustic_lookup.glsl: along
// the map's direction t, to the mean level). Such points are read by:
// - the passes that draw receivers seen straight from the camera (the floor, the receiver meshes),
//   and the marched godrays, which sample the map inside the water: all of them lie in the frustum,
//   within the box of points that project onto the map, between the lowest receiver and the
//   highest crest;
// - the water, the refraction scene view: receiver points met by rays refracted where the view
//   enters the surface (the frustum's part of the water's slab, level +- amplitude). Under flat
//   water a ray at theta_i from -y is refracted to asin(sin(theta_i) / n) from -y; a normal tilted
//   by up to atan(slope bound) turns the refracted ray by at most as much, so the ray goes at most
//   depth tan(asin(sin(theta_i) / n) + atan(slope)) sideways before it is as deep as the lowest
//   receiver.
// Each set is taken per block of the screen (8 x 8 sub-frusta, each with its own most oblique
// ray): the blocks' sets are convex, their images in the map convex polygons, and the read region
// is, per map row, the texels between the polygons' leftmost and rightmost points in that row,
// widened by what a read samples around its point (bilinear: one texel; the blur's radius).
// A photon leaves along the refracted sun, which a normal tilted by up to atan(slope) turns by at
// most as much (the same bound as for the view's rays): within a cone of that half-angle around
// the flat-water direction t, whose footprint per metre of depth is an ellipse of diameter
// tan(theta_t + tilt) - tan(theta_t - tilt); to that the crests' shift along t and the waves'
// sideways displacement (at most the amplitude) are added. That is photon_spread.
// Culling is off, with the reason, where the region is not bounded: the camera may be under the
// water (rays totally reflected under the surface can reach any point), the photons go to
// camera-space splats instead of the map, or the slope bound lets a refracted ray run
// horizontally.
#pragma once

#include "passes/caustics/caustics_light_space.hpp"

#include <glm/glm.hpp>

#include <cstdint>
#include <limits>
#include <memory>
#include <string>
#include <vector>

namespace vkw::passes {

struct CausticReadInputs {
    glm::dmat4 view_proj{1.0};  // the camera's, into reverse-Z clip space
    // Further cameras whose reads the region covers too: the other sub-frames of a supersampled
    // frame, which read the map that the first one makes (passes/frame/supersampled_frame.hpp).
    std::vector<glm::dmat4> more_views;
    double level = 0.0;             // the water's mean level, m
    double half_extent = 10.0;      // the water spans [-E, E]^2
    double amplitude = 0.0;         // a bound on the waves' height above the level, m
    double max_slope = 0.0;         // a bound on the surface's slope (WaterSurface::max_slope)
    double ior = 1.333;             // n of the water
    double lowest_receiver = -2.0;  // the floor's height, or the lowest receiver mesh's if lower, m
    bool camera_may_be_in_water = false;
    bool camera_space_splats = false;
    uint32_t read_margin = 1;  // texels a read may sample around its point (bilinear 1, + blur)

    bool operator==(const CausticReadInputs&) const = default;
};

struct CausticReadRegion {
    bool bounded = false;                     // false: every photon is kept
    uint32_t x0 = 0, y0 = 0, x1 = 0, y1 = 0;  // the read texels' bounding rectangle [x0, x1) x [y0, y1)
    std::vector<CausticTexelSpan> rows;       // per map row, the read texels (empty: none)
    std::shared_ptr<const std::vector<uint32_t>> packed_rows;  // pack_caustic_read_rows(rows), when bounded
    // How far, in m along each axis, a photon can land from where it would under flat water with
    // its surface point at the mean level (+infinity: no bound), so whole rows of cells that can
    // only land outside the read texels are not dispatched at all.
    double photon_spread = std::numeric_limits<double>::infinity();
    std::string note;  // the decision and its reason, for `vkwater passes`
};

CausticReadRegion caustic_read_region(const CausticMapFrame& frame, const CausticReadInputs& inputs);

// The last region and what it was computed from: a frame whose camera and water bounds have not
// moved (the waves' clock does not enter) reuses it. Computing it costs about 0.6 ms of CPU on
// pool, most of a frame's declaration.
class CausticReadRegionCache {
public:
    const CausticReadRegion& region(const CausticMapFrame& frame, const CausticReadInputs& inputs);
    uint64_t computed() const { return computed_; }  // how many times the region was computed

private:
    bool valid_ = false;
    CausticMapFrame frame_;
    CausticReadInputs inputs_;
    CausticReadRegion region_;
    uint64_t computed_ = 0;
};

}  // namespace vkw::passes
