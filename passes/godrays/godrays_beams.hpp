// The godray beams: one photon per cell of a coarse G x G grid over the water
// surface, traced exactly as the caustic photons are (shaders/caustics/caustic_photon.glsl: the
// cell's vector area, exact Fresnel, refraction, the same drop rules) but without extinction, so
// each carries Phi0 = E_s max(0, -s.a) T(theta_i), the flux just below the surface (docs/model.md
// section 6). Its beam runs from the entry point along the refracted direction t to the floor
// plane, or to max_depth below the mean level. The cell's corners are the GPU surface grid
// (passes/water/water_surface.hpp, R x R cells) interpolated bilinearly at i R / G: with G = R the
// beams are the caustic photons. When the sun shadow map is on the blackboard (objects and the sun
// up), a beam whose entry point the objects shade carries nothing.
// One compute pass ("godray beams", shaders/godrays/godray_beams.comp); the surface is bound in
// chunks of beam rows whose vertex rows fit maxStorageBufferRange.
#pragma once

#include "engine/framegraph/frame_graph.hpp"

#include <cstdint>

namespace vkw::passes {

// std430 struct GodrayBeam of shaders/godrays/godray_beam.glsl.
inline constexpr VkDeviceSize kGodrayBeamBytes = 48;

struct GodrayBeamInputs {
    fg::BufferHandle surface;           // the vertex grid of add_water_surface_pass
    uint32_t surface_resolution = 256;  // its R
    uint32_t grid = 64;                 // G: beams per side, 2..1024 (GodraySettings::grid sets it)
    double max_depth = 1e30;            // m below the mean level where beams stop
};

// Returns the beam buffer: G x G beams, row j (along z) after row j - 1. Reads the frame
// constants and, when present, the sun shadow map from the blackboard. Serves VolumeCaustics.
// Throws vkw::InternalError for a grid or resolution out of range.
fg::BufferHandle add_godray_beams_pass(fg::FrameGraph& graph, const GodrayBeamInputs& inputs);

}  // namespace vkw::passes
