// One godray beam (passes/godrays/godrays_beams.hpp): a photon of the coarse grid refracted into the water,
// from its entry point on the GPU surface along t to the floor (or the scene's max_depth). Written
// by godray_beams.comp, walked over the pixels by godray_lines.comp.
#ifndef VKWATER_GODRAY_BEAM_GLSL
#define VKWATER_GODRAY_BEAM_GLSL

// std430, 48 bytes. Mirrored by kGodrayBeamBytes in passes/godrays/godrays_beams.hpp.
struct GodrayBeam {
    vec4 entry;      // xyz: where the photon enters the water, m; w: the beam's length in the water, m (0: no beam)
    vec4 direction;  // xyz: the refracted direction t (unit, down); w: h, the side of its cell on the grid, m
    vec4 flux;       // rgb: Phi0, W: the flux just below the surface, before any attenuation; a: 0
};

#endif
