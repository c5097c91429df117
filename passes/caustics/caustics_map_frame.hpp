// What every producer of a caustic map (the photons' resolve, the procedural baseline, the blur)
// shares: the light-space frame (CausticLightSpacePush of fit_caustic_map), uploaded as the
// uniform buffer every receiver's lookup reads (shaders/caustics/caustic_lookup.glsl), and the
// map image's description.
#pragma once

#include "engine/framegraph/frame_graph.hpp"
#include "passes/caustics/caustics_light_space.hpp"

namespace vkw::passes {

fg::BufferHandle add_caustic_map_frame_pass(fg::FrameGraph& graph, const CausticInputs& inputs);

// The map's irradiance image: RGBA32F, the frame's W x H texels.
fg::ImageInfo caustic_map_image(const CausticMapFrame& frame);

}  // namespace vkw::passes
