// The scatter-only kernels of caustics_bench (shaders/caustics/bench/): one invocation per photon
// of an R x R grid, no tracing, each doing the 12 atomic adds (2 x 2 bilinear taps x RGB) of a
// photon pass photon whose taps are all non-zero, at the texels a flat-water photon of the same
// cell reaches in a map of one texel per cell. As frame-graph passes, so they are timed exactly
// as the caustic passes are (fence-timed on CPU devices).
#pragma once

#include "engine/framegraph/frame_graph.hpp"
#include "passes/caustics/caustics_light_space.hpp"

#include <shader_structs/caustics/bench/caustic_scatter_fixed.comp.hpp>

#include <string>

namespace vkwbench {

enum class ScatterKind {
    FixedPoint64,      // uint64 atomicAdd into a buffer laid out as the caustic flux (caustics_bands.hpp)
    FixedPoint64Tile,  // the same, through a workgroup tile in shared memory (needs shaderSharedInt64Atomics)
    FloatCas32,        // float adds by an atomicCompSwap loop on uint32 bits, three floats per texel
};

// The push constants of shaders/caustics/bench/caustic_scatter.glsl, generated from one of the
// kernels that include it (every kernel's is the same block): R photons per side, the map's
// texels, and the texels the fit added on each side for the waves' shift.
using ScatterPush = vkw::glsl::caustic_scatter_fixed_comp::Push;
inline constexpr uint32_t kScatterGroupSide = 8;  // local_size of caustic_scatter.glsl

// The kernels' constants for `resolution`^2 photons into the photon pass's map of `frame` (one
// texel per cell requested: the extra texels of the fit, caustics_light_space.hpp, split evenly).
ScatterPush scatter_push(uint32_t resolution, const vkw::passes::CausticMapFrame& frame);

std::string scatter_pass_name(ScatterKind kind);

// The bytes of a kind's target for a map of frame.width x frame.height texels.
VkDeviceSize scatter_target_bytes(ScatterKind kind, const vkw::passes::CausticMapFrame& frame);

// Adds the zeroing of the target (its own pass) and the scatter pass for `resolution`^2 photons
// into a map of frame.width x frame.height texels (the photon pass's map for the same inputs);
// returns the target. Throws vkw::InternalError when the target exceeds one storage-buffer binding,
// or for the tile kind on a device without shared-memory int64 atomics.
vkw::fg::BufferHandle add_caustic_scatter_pass(vkw::fg::FrameGraph& graph, ScatterKind kind, uint32_t resolution,
                                               const vkw::passes::CausticMapFrame& frame);

}  // namespace vkwbench
