// The receivers the camera sees without the water (Ojeda & Susín 2013 section 4, step 1), for the
// camera-space caustic splats (passes/caustics/caustics_camera_splats.hpp): the floor plane and the receiver
// meshes below the mean level plus the clip margin, drawn from the camera with the scene views'
// guard band (shaders/scene_views/scene_view.glsl, so photons and refracted view rays that land
// just off the screen still find their receiver), each texel holding the receiver's unit normal
// turned toward the eye and its distance from the eye (0 where no receiver is seen).
#pragma once

#include "engine/framegraph/frame_graph.hpp"
#include "passes/receivers/receiver_meshes.hpp"

#include <cstdint>

namespace vkw::passes {

// The view's size for an output of width x height: the guard band at the camera's pixel density.
struct CameraCausticExtent {
    uint32_t width = 0, height = 0;
};
CameraCausticExtent camera_caustic_extent(uint32_t output_width, uint32_t output_height);

// Returns the RGBA32F view (normal, distance) of camera_caustic_extent(width, height) pixels.
// `meshes` may be null (the floor alone).
fg::ImageHandle add_caustic_receivers_pass(fg::FrameGraph& graph, const ReceiverMeshes* meshes,
                                           CameraCausticExtent extent, float clip_margin);

}  // namespace vkw::passes
