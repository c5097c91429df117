// The scene's receivers and objects (built-in shapes and glTF meshes) drawn as
// Lambertian surfaces over the sky and the floor, lit above or under the water by the
// floor's shader (shaders/receivers/receiver.frag); above the water the sun is shadowed by
// the objects through the sun shadow map (passes/receivers/sun_shadow.hpp); under it by the caustic map
// (passes/caustics/caustics_*), or where the caustics are culled by the flat-surface stand-in shadowed
// along the refracted beam. Not yet: textures.
// Reads and republishes keys::kHdrColor and keys::kSceneDepth.
#pragma once

#include "engine/framegraph/frame_graph.hpp"
#include "passes/receivers/receiver_meshes.hpp"

namespace vkw::passes {

void add_receivers_pass(fg::FrameGraph& graph, const ReceiverMeshes& meshes);

}  // namespace vkw::passes
