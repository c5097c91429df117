// The scene's receivers and objects (built-in shapes and glTF meshes) drawn as
// Lambertian surfaces over the sky and the floor, lit above or under the water like the
// floor (shaders/receivers/mesh.frag). Not yet: shadows from other objects, textures.
// Reads and republishes keys::kHdrColor and keys::kSceneDepth.
#pragma once

#include "engine/framegraph/frame_graph.hpp"
#include "passes/receiver_meshes.hpp"

namespace vkw::passes {

void add_receivers_pass(fg::FrameGraph& graph, const ReceiverMeshes& meshes);

}  // namespace vkw::passes
