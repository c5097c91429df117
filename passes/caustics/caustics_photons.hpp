// The photon grid of the surface caustics:
// one compute pass that traces S x S photons per cell of the GPU water grid (S = 1: one photon per
// cell, its intercepted area the cell's true vector area; shaders/caustics/caustic_photon.glsl),
// refracts them with the exact Fresnel of common/fresnel.glsl, carries them to the floor plane,
// and splats each photon's flux
//   Phi = E_s max(0, -s.a) T(theta_i) exp(-sigma_t l)      (a: the sub-cell's vector area)
// with its kernel (the 2x2 bilinear tent; caustic_splat.glsl: the hat of the landed photon
// lattice, whose photons carry what their hats intercept rather than their sub-cells' area;
// caustic_footprint.glsl: its sub-cell's footprint by area; each a shader
// variant; the taps sum to the photon's flux exactly, in integers) into the light-space
// caustic flux map of fit_caustic_map, accumulated with uint64 fixed-point atomics
// (caustics_light_space.hpp gives the LSB and the headroom), so two runs are bit-identical.
// Dropped photons: the cell faces away from the sun, the refracted ray points up
// (t.y > -1e-6), the surface lies below the floor, the sun is not above the horizon, or (with the
// sun shadow map) an object above the water shadows the entry point; non-finite flux (dropped at
// its producer, so nothing downstream sees a NaN).
// Receivers: the floor plane, exactly; with the sun shadow map, also the receiver meshes under
// the water as its beam half sees them along the flat-water refracted sun (the caustic map's own
// direction), found by shaders/caustics/caustic_receiver_hit.glsl. A photon whose ray leaves that
// map continues to the floor plane (the map covers every mesh under the water, so it misses none).
// Options (CausticInputs): S x S photons per cell, jitter, the kernel.
//
// Chunked: cell rows are dispatched in chunks whose vertex rows fit one binding, map rows in bands
// that fit one binding (caustics_bands.hpp); every dispatch stays within 65535 groups per side.
#pragma once

#include "engine/framegraph/frame_graph.hpp"
#include "engine/framegraph/pass_context.hpp"
#include "passes/caustics/caustics_bands.hpp"
#include "passes/caustics/caustics_light_space.hpp"
#include "passes/receivers/sun_shadow.hpp"

#include <vector>

namespace vkw::passes {

// What the push constants of every photon kernel begin with (struct CausticPhotonSource of
// shaders/caustics/caustic_photon_source.glsl, generated once from common/shared_blocks.comp): the
// light-space frame, E_s / LSB and sigma_t.
using CausticPhotonSourcePush = glsl::shared_blocks_comp::CausticPhotonSource;
static_assert(sizeof(CausticPhotonSourcePush) == 96);

// Throws vkw::InternalError for inputs out of range.
CausticPhotonSourcePush caustic_photon_source(const CausticInputs& inputs);

// The photon grid's dispatches: chunks of cell rows whose vertex rows fit one storage binding
// and whose S x S photons per cell stay within 65535 groups of 8 per side. `neighbour_rows`: the
// binding must also hold the rows the adaptive kernel's neighbours are in, one before the chunk
// and one after it, from an aligned offset.
std::vector<RowBand> caustic_photon_chunks(const fg::PassContext& context, uint32_t resolution, uint32_t sub,
                                           bool neighbour_rows = false);

// Adds the clear of the flux buffer (transfer) and the photon pass (compute) and returns the
// flux buffer: caustic_flux_bytes(W, H) bytes, the held texels laid out as caustics_bands.hpp says
// (taps on the map outside them are dropped: no pass reads there), in units of
// fit_caustic_map(inputs).lsb. `shadow` (scenes with receiver meshes): the sun shadow map, whose
// beam half must look along fit_caustic_map(inputs).direction. Throws vkw::InternalError for
// inputs out of range.
fg::BufferHandle add_caustic_photon_pass(fg::FrameGraph& graph, const CausticInputs& inputs,
                                         const SunShadowMap* shadow = nullptr);

}  // namespace vkw::passes
