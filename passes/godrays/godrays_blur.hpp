// One direction of the godray blur (shaders/godrays/godray_blur.comp): binomial
// weights 1 4 6 4 1 / 16 along x or y, taps on another surface (scene distance off by more than 5%)
// left out and the rest renormalised. Run along x, then along y: a 5 x 5 binomial kernel of
// variance 1 pixel^2 per axis that never carries light across a depth edge.
#pragma once

#include "engine/framegraph/frame_graph.hpp"

namespace vkw::passes {

enum class BlurAxis { X, Y };

// `image` and `view_depth` (add_godray_depth_pass) at `scale` of the output; returns the blurred
// image. Serves VolumeCaustics.
fg::ImageHandle add_godray_blur_pass(fg::FrameGraph& graph, fg::ImageHandle image, fg::ImageHandle view_depth,
                                     float scale, BlurAxis axis);

}  // namespace vkw::passes
