// The godrays added to the HDR colour (shaders/godrays/godray_composite.frag): a
// full-screen triangle with additive blending that upsamples the godray radiance depth-aware (the
// bilinear taps on this pixel's surface; the nearest in distance where none is). The radiance
// already holds T / n^2 where the view enters the water from above, so this is a plain sum.
// Publishes the new keys::kHdrColor.
#pragma once

#include "engine/framegraph/frame_graph.hpp"

namespace vkw::passes {

// `radiance` and `view_depth` at the godray resolution. Reads the frame constants, the scene depth
// and the HDR colour. Serves VolumeCaustics.
void add_godray_composite_pass(fg::FrameGraph& graph, fg::ImageHandle radiance, fg::ImageHandle view_depth);

}  // namespace vkw::passes
