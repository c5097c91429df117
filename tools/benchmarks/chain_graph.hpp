// The frame-graph test chain: a compute pass writes a pattern into a storage image
// (texel (x, y) = (x, y, x + y, 1)), a graphics pass samples it into a colour
// attachment doubling it, and the caller reads that back. Shared by the GPU test of
// the frame graph and by the recording-overhead benchmark.
#pragma once

#include "engine/framegraph/frame_graph.hpp"

namespace vkw::chain {

inline constexpr const char* kPatternShader = "tests/gradient.comp";
inline constexpr const char* kCopyShader = "tests/copy_texels.frag";

// Returns the doubled image; the graph's output size is the image size.
fg::ImageHandle add_chain(fg::FrameGraph& graph);

}  // namespace vkw::chain
