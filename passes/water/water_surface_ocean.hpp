// The FFT ocean on the GPU: h0 imported from an OceanSpectrumBuffer, the spectra at time t
// (shaders/water/ocean_spectra.comp), the inverse FFT (water_surface_fft.hpp), and the vertex
// grid sampled from the periodic result (shaders/water/ocean_grid.comp).
#pragma once

#include "engine/framegraph/frame_graph.hpp"
#include "passes/water/water_surface.hpp"

namespace vkw::passes {

// The fields after the FFT: two n x n grids of vec4, grid q holding the OceanFields 4q .. 4q + 3
// in x, y, z, w (node (ix, iz) at q n^2 + iz n + ix): the complex planes 2q (xy) and 2q + 1
// (zw), plane p carrying field 2p in its real and 2p + 1 in its imaginary part. After them one
// vec4 more, element 2 n^2: x, the largest |h| over the nodes this frame (the "ocean height bound"
// pass, shaders/water/ocean_height_bound.comp), which bounds the whole surface's height.
inline constexpr uint32_t kOceanGridCount = 2;

// inputs.ocean must match inputs.waves.ocean (add_water_surface_passes checks).
WaterSurfaceBuffers add_ocean_passes(fg::FrameGraph& graph, const WaterSurfaceInputs& inputs, uint32_t mesh_resolution);

}  // namespace vkw::passes
