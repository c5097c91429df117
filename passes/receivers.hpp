// The scene's receivers and objects (built-in shapes and glTF meshes) drawn as
// Lambertian surfaces over the sky and the floor, lit above or under the water by the
// floor's shader (shaders/receivers/receiver.frag); above the water the sun is shadowed by
// the objects through the sun shadow map (passes/sun_shadow.hpp). Not yet: shadows under
// the water (along the refracted beam), textures, and caustics on them (the caustic map is traced to the floor plane: under
// the water they keep the flat-surface stand-in).
// Reads and republishes keys::kHdrColor and keys::kSceneDepth.
#pragma once

#include "engine/framegraph/frame_graph.hpp"
#include "passes/receiver_meshes.hpp"

namespace vkw::passes {

void add_receivers_pass(fg::FrameGraph& graph, const ReceiverMeshes& meshes);

}  // namespace vkw::passes
