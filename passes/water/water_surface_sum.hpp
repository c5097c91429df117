// The wave-sum model on the GPU (and flat water, a sum of no waves): an upload pass writes
// the per-wave constants, a compute pass evaluates shaders/water/wave_sum.comp at every vertex.
#pragma once

#include "engine/framegraph/frame_graph.hpp"
#include "engine/water/wave_params.hpp"
#include "passes/water/water_surface.hpp"

#include <vector>

namespace vkw::passes {

// Uploads the wave table of `waves` at `time` (a buffer of kMaxGpuWaves entries, the first
// max(1, waves.size()) written; the shaders read only the waves' count of them) and
// returns it: the grid kernel's input and, for the per-pixel refinement, a uniform buffer.
fg::BufferHandle add_wave_table_pass(fg::FrameGraph& graph, const std::vector<WaveComponent>& waves, double time);

// `waves`: at most kMaxGpuWaves, already validated (add_water_surface_passes checks both).
WaterSurfaceBuffers add_wave_sum_passes(fg::FrameGraph& graph, const WaterSurfaceInputs& inputs,
                                        const std::vector<WaveComponent>& waves, uint32_t mesh_resolution);

}  // namespace vkw::passes
