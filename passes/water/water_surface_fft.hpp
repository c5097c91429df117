// The inverse 2D FFT of the GPU ocean: shaders/water/ocean_fft.comp over the rows, then over
// the columns, of `grid_count` n x n grids stored one after another (row-major), in place.
// Each grid element is a vec4 of two complex numbers (xy, zw) transformed independently, as
// the ocean moves its fields in pairs. Two compute passes; the graph puts the barrier
// between them.
#pragma once

#include "engine/framegraph/frame_graph.hpp"

#include <cstdint>

namespace vkw::passes {

// For each complex plane (the xy or the zw parts of one grid) the unnormalised inverse DFT of
// engine/water/fft.hpp fft_inverse_2d:
//   out[r][c] = sum over (b, a) of in[b][a] exp(+2 pi i (a c + b r) / n).
// n a power of two in [16, 1024] and 1 <= grid_count <= 65535 * 1024 / n^2 (the work groups
// of one dispatch), or vkw::InternalError. Returns the buffer's version after the columns pass.
fg::BufferHandle add_inverse_fft_passes(fg::FrameGraph& graph, fg::BufferHandle grids, uint32_t n, uint32_t grid_count);

}  // namespace vkw::passes
