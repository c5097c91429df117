// The godrays added to the HDR colour (shaders/godrays/godray_composite.frag): a
// full-screen triangle with additive blending that upsamples the godray radiance depth-aware (the
// bilinear taps on this pixel's surface; the nearest in distance where none is). The radiance
// already holds T / n^2 where the view enters the water from above, so this is a plain sum.
// Publishes the new keys::kHdrColor, and with `inscatter_layer` the same radiance alone as a second
// colour target (keys::kInScatterLayer): the in-scatter layer, EXR channels inscatter.R/G/B.
#pragma once

#include "engine/framegraph/frame_graph.hpp"

namespace vkw::passes {

// `radiance` and `view_depth` at the godray resolution. Reads the frame constants, the scene depth
// and the HDR colour. Serves VolumeCaustics.
void add_godray_composite_pass(fg::FrameGraph& graph, fg::ImageHandle radiance, fg::ImageHandle view_depth,
                               bool inscatter_layer);

}  // namespace vkw::passes

namespace vkw::keys {

// RGBA32F, output size: the single-scattered radiance alone that the godrays add to each pixel (the
// primary view ray's path in the water, carried to the camera: T / n^2 through the surface from
// above), 0 where they add none. Only when asked for and the godrays run.
inline constexpr fg::BlackboardKey<fg::ImageHandle> kInScatterLayer{"in-scatter layer"};

}  // namespace vkw::keys
