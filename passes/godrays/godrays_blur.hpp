// The godray blur (shaders/godrays/godray_blur.comp), one pass along x and one along y: binomial
// weights 1 4 6 4 1 / 16 on each axis, taps on another surface (scene distance off by more than 5%)
// left out and the rest renormalised. Together a 5 x 5 binomial kernel of variance 1 pixel^2 per
// axis that never carries light across a depth edge.
#pragma once

#include "engine/framegraph/frame_graph.hpp"

namespace vkw::passes {

// `image` and `view_depth` (add_godray_depth_pass) at `scale` of the output; returns the blurred
// image. Serves VolumeCaustics.
fg::ImageHandle add_godray_blur(fg::FrameGraph& graph, fg::ImageHandle image, fg::ImageHandle view_depth, float scale);

}  // namespace vkw::passes
