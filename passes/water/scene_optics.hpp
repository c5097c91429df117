// The water's optical constants for the frame (the refracted sun, E_perp just below the
// surface, T_hemi), computed once on the device by shaders/water/scene_optics.comp
// from the shared Fresnel include. Publishes keys::kSceneOptics.
#pragma once

#include "engine/framegraph/blackboard.hpp"
#include "engine/framegraph/frame_graph.hpp"

namespace vkw::passes {

void add_scene_optics_pass(fg::FrameGraph& graph);

}  // namespace vkw::passes

// The key under which this pass publishes its output (a typed blackboard, as in Filament).
namespace vkw::keys {

inline constexpr fg::BlackboardKey<fg::BufferHandle> kSceneOptics{"scene optics"};

}  // namespace vkw::keys
