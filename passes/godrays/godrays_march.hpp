// The marched baseline of the godrays (shaders/godrays/godray_march.comp): each
// godray pixel's view ray is followed through the water in `steps` equal steps per segment (from a
// camera in the water to the scene, and on along the surface's reflection; from the air along the
// ray refracted by the flat surface, times T / n^2). At each step's midpoint the sun's light is the
// flat beam, modulated by the caustic map when keys::kCausticMap is on the blackboard and shadowed
// by the sun shadow map when keys::kSunShadow is; the view transmittance is integrated over the
// step analytically. Writes the same godray radiance image as the lines (before the upsampling).
#pragma once

#include "engine/framegraph/frame_graph.hpp"

#include <cstdint>

namespace vkw::passes {

struct GodrayMarchInputs {
    fg::ImageHandle view_depth;  // add_godray_depth_pass's output
    float scale = 0.5f;          // its size relative to the output
    uint32_t steps = 32;         // per view segment, 1..4096
    double max_amplitude = 0.0;  // m: a bound on the waves' height above the mean level
    double max_depth = 1e30;     // m below the mean level where the light stops
};

// RGBA32F radiance at `scale` of the output. Serves VolumeCaustics.
fg::ImageHandle add_godray_march_pass(fg::FrameGraph& graph, const GodrayMarchInputs& inputs);

}  // namespace vkw::passes
