// The caustic map's density-adaptive, energy-preserving blur
// (shaders/caustics/caustic_blur.comp): two separable passes over the resolved irradiance map,
// each source texel spread over a tent whose width grows where photons are sparse
// (r = r0 sqrt(E_flat / E), at most 4 texels; r0 = effects.caustic_blur.radius), with weights
// normalised over the taps on the map, so the map's total flux is kept to fp32 rounding. The
// photon pass has already dropped non-finite flux at its producer, so the blur spreads no NaN.
// Serves Effect::CausticBlur; returns the blurred map (the same light-space frame).
#pragma once

#include "engine/framegraph/frame_graph.hpp"
#include "passes/caustics/caustics_light_space.hpp"
#include "passes/caustics/caustics_resolve.hpp"

namespace vkw::passes {

// The radius cap, texels (kMaxBlurRadius of caustic_blur.comp).
constexpr double kMaxCausticBlurRadius = 4.0;

// `map` is add_caustic_resolve_pass(graph, flux, inputs) with the same inputs; `radius` is r0
// in texels, in [0, kMaxCausticBlurRadius] (0: the identity).
CausticMap add_caustic_blur_pass(fg::FrameGraph& graph, const CausticMap& map, const CausticInputs& inputs,
                                 double radius);

}  // namespace vkw::passes
