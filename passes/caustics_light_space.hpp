// The inputs of the caustic passes and the light-space frame of their map (issue 7 items 2-4,
// the floor as the receiver), computed once on the CPU in double:
// - basis: Duff et al.'s branchless orthonormal basis around the sun direction s, finite for a
//   sun exactly overhead (no cross(up, s));
// - fit: orthographic along s, fitted to where the floor receives light through flat water: the
//   water's extent (its corners at level +- max_amplitude) carried to the floor along the
//   flat-water refracted direction, then projected along s, plus fit_margin metres on each side
//   (room for the sideways deflection by waves) and one texel of border, so the 2x2 kernel of an
//   edge photon stays on the map. With n = 1 this is exactly the water's extent projected along s.
// - fixed point: the map accumulates flux in uint64 units of LSB_c (per channel c), with
//     LSB_c = max(1e-9 Phi_flat_c, Phi_in_c / 2^62),
//   Phi_flat_c = E_s,c T(theta_s) exp(-sigma_t,c d / cos theta_t) A_ls, the flux of one texel
//   under flat water, and Phi_in_c a bound on the flux the whole surface can intercept. So the LSB
//   is at most 1e-9 of the flat-water texel flux whenever the uint64 can also hold all the
//   incoming flux (9e9 x the flat value before signed overflow, 1.8e10 x before unsigned: the
//   headroom), and otherwise the second term makes overflow impossible: the sum of all deposits
//   is at most 2^62 + the rounding of at most 4 per photon tap.
#pragma once

#include "engine/framegraph/frame_graph.hpp"

#include <glm/glm.hpp>

#include <cstdint>

namespace vkw::passes {

struct CausticInputs {
    fg::BufferHandle surface;             // the vertex grid of add_water_surface_pass
    uint32_t grid_resolution = 256;       // its R (cells per side)
    double water_level = 0.0;             // its mean level y, m
    double half_extent = 10.0;            // its E: the grid spans [-E, E]^2
    double max_amplitude = 0.0;           // a bound on |h| (WaterSurface::max_amplitude), for the fit
    uint32_t sub_photons = 1;             // S: S x S photons per cell (S = 1: one per cell)
    glm::dvec3 sun_direction{0.0, -1.0, 0.0};  // unit, the direction the sunlight travels
    glm::dvec3 sun_irradiance{1.0};       // E_s per RGB, W m^-2 normal to the beam
    double ior = 1.333;                   // n of the water, [1, 2]
    glm::dvec3 sigma_t{0.0};              // extinction per RGB, 1/m
    double floor_height = -2.0;           // the receiver: the plane y = floor_height
    double fit_margin = 0.0;              // m added around the fitted map on each side
    uint32_t map_width = 512, map_height = 512;  // W x H texels, 3..16384 each
};

// Mirrors struct CausticLightSpace of shaders/caustics/caustic_light_space.glsl.
struct CausticLightSpacePush {
    float origin[4];  // xyz, floor height
    float u_axis[4];  // u / texel_u, W
    float v_axis[4];  // v / texel_v, H
    float sun[4];     // s, n
};
static_assert(sizeof(CausticLightSpacePush) == 64);

struct CausticMapFrame {
    glm::dvec3 s, u, v;          // the sun direction and the map's axes (orthonormal)
    glm::dvec2 corner;           // (u, v) of texel coordinate (0, 0), m
    glm::dvec2 texel;            // texel size along u and v, m
    double texel_area = 0.0;     // A_ls = texel.x texel.y, m^2 normal to the sun
    uint32_t width = 0, height = 0;
    bool sun_up = false;         // s.y < 0; otherwise no photon deposits anything
    glm::dvec3 flat_texel_flux;  // Phi_flat per channel (above), W
    glm::dvec3 lsb;              // W per fixed-point unit, per channel
};

// Duff, Burgess, Christensen, Hery, Kensler, Liani, Villemin, "Building an Orthonormal Basis,
// Revisited" (JCGT 2017): (u, v) with (u, v, s) orthonormal, continuous except across s.z = 0,
// where copysign picks a side. s = (0, -1, 0) gives u = +x, v = +z.
void branchless_basis(const glm::dvec3& s, glm::dvec3& u, glm::dvec3& v);

// Throws vkw::InternalError for inputs outside the documented ranges or a non-unit sun.
CausticMapFrame fit_caustic_map(const CausticInputs& inputs);

CausticLightSpacePush caustic_light_space_push(const CausticMapFrame& frame, const CausticInputs& inputs);

}  // namespace vkw::passes
