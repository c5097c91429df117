// The caustic map's light-space frame (CausticLightSpacePush of fit_caustic_map), uploaded as the
// uniform buffer every receiver's lookup reads (shaders/caustics/caustic_lookup.glsl). Shared by
// the producers of a caustic map: the photons' resolve and the procedural baseline.
#pragma once

#include "engine/framegraph/frame_graph.hpp"
#include "passes/caustics_light_space.hpp"

namespace vkw::passes {

fg::BufferHandle add_caustic_map_frame_pass(fg::FrameGraph& graph, const CausticInputs& inputs);

}  // namespace vkw::passes
