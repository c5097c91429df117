// The water's optical constants for the frame (the refracted sun, E_perp just below the
// surface, T_hemi), computed once on the device by shaders/water_shading/scene_optics.comp
// from the shared Fresnel include. Publishes keys::kSceneOptics.
#pragma once

#include "engine/framegraph/frame_graph.hpp"

namespace vkw::passes {

void add_scene_optics_pass(fg::FrameGraph& graph);

}  // namespace vkw::passes
