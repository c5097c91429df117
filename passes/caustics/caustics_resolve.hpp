// The caustic map a receiver samples: the fixed-point flux of
// add_caustic_photon_pass converted to irradiance on a plane normal to the sun,
// E_perp = Phi_texel / A_ls per RGB, in an RGBA32F image (W x H, alpha 1), plus the uniform
// buffer of its light-space frame. A receiver converts with E = E_perp |s . N_r| by including
// shaders/caustics/caustic_lookup.glsl (caustic_irradiance(world_position, normal)) with the
// image bound as a sampler2D and the frame as the CausticLightSpace uniform block.
#pragma once

#include "engine/framegraph/blackboard.hpp"
#include "engine/framegraph/frame_graph.hpp"
#include "passes/caustics/caustics_light_space.hpp"

namespace vkw::passes {

struct CausticMap {
    fg::ImageHandle irradiance;  // RGBA32F, written as a storage image
    fg::BufferHandle frame;      // uniform: CausticLightSpacePush (std140)
};

// `flux` is add_caustic_photon_pass(graph, inputs) with the same inputs.
CausticMap add_caustic_resolve_pass(fg::FrameGraph& graph, fg::BufferHandle flux, const CausticInputs& inputs);

}  // namespace vkw::passes

// The key under which this pass publishes its output (a typed blackboard, as in Filament).
namespace vkw::keys {

inline constexpr fg::BlackboardKey<passes::CausticMap> kCausticMap{"caustic map"};

}  // namespace vkw::keys
