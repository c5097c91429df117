// The inputs of the caustic passes and the light-space frame of their map,
// computed once on the CPU in double:
// - direction: the map is a projection along the flat-water refracted sun t (the beam's mean
//   direction under the water), so every receiver point the flat beam reaches is visible in it:
//   a tilted plane, the sides of a box, a sphere's lit half each get texels of their own, and a
//   receiver converts the flux of its texel with its own normal, E = Phi_texel max(0, -t.N) / A_ls.
//   The receivers seen along t are the sun shadow map's beam half (passes/receivers/sun_shadow.hpp), which
//   the photons are traced against; the floor plane is exact.
// - parametrisation: a point's map position is where the line along t through it crosses the
//   mean level (an oblique projection, affine in the point, finite for every sun: t.y <= -cos
//   theta_t < 0). The water grid's cells are then the map's texels (W - 2 = R: texel = cell),
//   so under flat water each photon lands on a texel centre (no moire between a rotated photon
//   lattice and the texels) and under waves only the waves' deflection moves it. A texel's area
//   normal to t is A_ls = texel_x texel_z cos(theta_t).
// - fit: the water's extent, plus as many texels on each side as the crests' shift along t
//   (max_amplitude |t.xz / t.y|) and fit_margin need, plus a border as wide as the splat
//   kernel reaches (one texel for the bilinear 2x2, kAdaptiveSplatReach for the adaptive one,
//   kMaxFootprintTexels for the footprint),
//   so the kernel of an edge photon stays on the map. The map is therefore wider than the requested
//   W x H when the water has waves (CausticMapFrame::width, height).
// - fixed point: the map accumulates flux in uint64 units of LSB_c (per channel c), with
//     LSB_c = max(1e-9 Phi_flat_c, Phi_in_c / 2^62),
//   Phi_flat_c = E_s,c T(theta_s) (cos theta_s / cos theta_t) exp(-sigma_t,c d / cos theta_t) A_ls,
//   the flux of one texel (area A_ls normal to t) on the floor under flat water, and Phi_in_c a
//   bound on the flux the whole surface can intercept. So the LSB is at most 1e-9 of the
//   flat-water texel flux whenever the uint64 can also hold all the incoming flux (9e9 x the flat
//   value before signed overflow, 1.8e10 x before unsigned: the headroom), and otherwise the
//   second term makes overflow impossible: the sum of all deposits is at most 2^62 + the rounding
//   of at most 4 per photon tap.
#pragma once

#include "engine/framegraph/frame_graph.hpp"
#include "engine/scene/scene.hpp"

#include <glm/glm.hpp>
#include <shader_structs/common/shared_blocks.comp.hpp>

#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace vkw::passes {

// How far the adaptive splat's taps reach from the texel of its photon's node, texels
// (kAdaptiveSplatReach of caustic_splat.glsl), and the footprint splat's largest extent per axis
// (kMaxFootprintTexels of caustic_footprint.glsl).
constexpr uint32_t kAdaptiveSplatReach = 6;
constexpr uint32_t kMaxFootprintTexels = 8;

// A rectangle of map texels, [x0, x1) x [y0, y1).
struct CausticTexelRect {
    uint32_t x0 = 0, y0 = 0, x1 = 0, y1 = 0;

    uint32_t width() const { return x1 - x0; }
    uint32_t height() const { return y1 - y0; }
    bool operator==(const CausticTexelRect&) const = default;
};
// The texels [x0, x1) of one map row.
struct CausticTexelSpan {
    uint32_t x0 = 0, x1 = 0;
};
// The photon pass's read rows (its `ReadRows`): per map row its span as x0 | x1 << 16, then the
// same widened by kAdaptiveSplatReach texels along both axes (the rows within it merged), so that
// a photon's node alone says whether its hat can reach a read texel. Twice the map's height.
std::vector<uint32_t> pack_caustic_read_rows(const std::vector<CausticTexelSpan>& spans);

// The texels a frame reads: their bounding rectangle and, per map row, their span, packed for the
// photon pass (shared: made once per read region, not per frame).
struct CausticReadTexels {
    CausticTexelRect bounds;
    std::shared_ptr<const std::vector<uint32_t>> packed_rows;  // pack_caustic_read_rows of the spans
    double photon_spread = 0.0;                                // m: how far a photon can land from its cell's own place
};

struct CausticInputs {
    fg::BufferHandle surface;                        // the vertex grid of add_water_surface_pass
    uint32_t grid_resolution = 256;                  // its R (cells per side)
    double water_level = 0.0;                        // its mean level y, m
    double half_extent = 10.0;                       // its E: the grid spans [-E, E]^2
    double max_amplitude = 0.0;                      // a bound on |h| (WaterSurface::max_amplitude), for the fit
    uint32_t sub_photons = 1;                        // S: S x S photons per cell (S = 1: one per cell)
    bool jitter = false;                             // photons leave from hashed points of their sub-cells
    CausticKernel kernel = CausticKernel::Bilinear;  // the splat (shaders/caustics/caustic_splat.glsl)
    // The adaptive kernel's lanes hand each other their photons' rays where the device has subgroup
    // shuffles; false makes each lane trace its neighbours itself (the same map bit for bit).
    bool share_rays_between_lanes = true;
    glm::dvec3 sun_direction{0.0, -1.0, 0.0};    // unit, the direction the sunlight travels
    glm::dvec3 sun_irradiance{1.0};              // E_s per RGB, W m^-2 normal to the beam
    double ior = 1.333;                          // n of the water, [1, 2]
    glm::dvec3 sigma_t{0.0};                     // extinction per RGB, 1/m
    double floor_height = -2.0;                  // the receiver: the plane y = floor_height
    double fit_margin = 0.0;                     // m added around the fitted map on each side
    uint32_t map_width = 512, map_height = 512;  // W x H texels, 3..16384 each
    // The texels the frame can read (caustics_read_region.hpp): a photon whose kernel reaches none
    // of them is left out. Empty: every photon is kept. read_note says which, and why.
    std::optional<CausticReadTexels> read_texels;
    std::string read_note;
    // The flux and the resolved map hold only the read texels' bounding rectangle
    // (CausticMapFrame::held), so that clearing and resolving cost what the frame reads. Off where
    // a pass reads around every texel of the map (the blur).
    bool hold_read_texels_only = false;
};

// struct CausticLightSpace of shaders/caustics/caustic_light_space.glsl (origin: xyz, floor height;
// u_axis: u / texel_u, W; v_axis: v / texel_v, H; sun: s, n), generated once from
// common/shared_blocks.comp; four vec4, the same in std140 and std430.
using CausticLightSpacePush = glsl::shared_blocks_comp::CausticLightSpace;
static_assert(sizeof(CausticLightSpacePush) == 64);

struct CausticMapFrame {
    glm::dvec3 s;             // the sun direction
    glm::dvec3 direction;     // t: the map's projection direction (the flat-water refracted sun)
    glm::dvec2 shear;         // -t.xz / t.y: a point's map position is (x, z) + (y - level) shear
    glm::dvec2 corner;        // (x, z) at the mean level of texel coordinate (0, 0), m
    glm::dvec2 texel;         // texel size along x and z at the mean level, m
    double texel_area = 0.0;  // A_ls = texel.x texel.y cos(theta_t), m^2 normal to t
    uint32_t width = 0, height = 0;
    // The texels the flux buffer and the resolved map hold this frame: the read texels' bounding
    // rectangle with CausticInputs::hold_read_texels_only, else the whole map. Both are allocated
    // for the whole map (its bound), so a rectangle that moves with the camera allocates nothing.
    // The flux holds the rectangle's rows at its own width; the map holds it at its place, and its
    // other texels are undefined: every reader reads within it (caustics_read_region.hpp).
    CausticTexelRect held;
    bool sun_up = false;         // s.y < 0; otherwise no photon deposits anything
    glm::dvec3 flat_texel_flux;  // Phi_flat per channel (above), W
    glm::dvec3 lsb;              // W per fixed-point unit, per channel

    // Whether the held texels are only part of the map (the photons, the clear and the resolve
    // then address the rectangle alone).
    bool holds_part() const { return held != CausticTexelRect{0, 0, width, height}; }
    bool operator==(const CausticMapFrame&) const = default;
};

// Duff, Burgess, Christensen, Hery, Kensler, Liani, Villemin, "Building an Orthonormal Basis,
// Revisited" (JCGT 2017): (u, v) with (u, v, s) orthonormal, continuous except across s.z = 0,
// where copysign picks a side. s = (0, -1, 0) gives u = +x, v = +z.
void branchless_basis(const glm::dvec3& s, glm::dvec3& u, glm::dvec3& v);

// Throws vkw::InternalError for inputs outside the documented ranges or a non-unit sun.
CausticMapFrame fit_caustic_map(const CausticInputs& inputs);

CausticLightSpacePush caustic_light_space_push(const CausticMapFrame& frame, const CausticInputs& inputs);

}  // namespace vkw::passes
