// Godrays, the volume caustics: the in-scatter of the sun's refracted beams along the
// view rays in the water (docs/model.md section 6), in place of the shading's analytic in-scatter
// (the renderer clears frame.medium_options.x while these passes run: counted once). Two methods
// (effects.godrays.method):
//   lines    add_godray_beams_pass -> add_godray_depth_pass -> add_godray_lines_passes ->
//            add_godray_resolve_pass -> add_godray_blur (x, y) -> add_godray_composite_pass
//   marched  add_godray_depth_pass -> add_godray_march_pass -> add_godray_composite_pass
// at the godray resolution (the output's, or half of it per side), added to the HDR colour.
// Every pass serves Effect::VolumeCaustics.
// Not yet: beams blocked by objects under the water; the view through a wavy surface from above
// (the lines and the march refract at the flat surface of the mean level).
#pragma once

#include "engine/framegraph/frame_graph.hpp"
#include "engine/scene/scene.hpp"

#include <cstdint>
#include <string>

namespace vkw::passes {

struct GodrayInputs {
    fg::BufferHandle surface;           // the vertex grid of add_water_surface_pass
    uint32_t surface_resolution = 256;  // its R
    double max_amplitude = 0.0;         // m: a bound on the waves' height above the mean level
    GodraySettings settings;
    uint32_t width = 800, height = 600;  // the output's size
    bool inscatter_layer = false;        // also the in-scatter layer (keys::kInScatterLayer)
};

// Declares the passes after the water shading; reads keys::kFrameConstants, kSceneOptics,
// kSceneDepth, kHdrColor and, when present, kCameraMedium, kCausticMap, kSunShadow; publishes the
// new kHdrColor (and kInScatterLayer when asked for).
void add_godray_passes(fg::FrameGraph& graph, const GodrayInputs& inputs);

}  // namespace vkw::passes
