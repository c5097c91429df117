// The one function that decides, from the scene and its camera, which effects a
// frame needs, each with its reason. The foundation renders no water yet, so it
// decides nothing and the graph requests only the final image; the scenes issue
// and each effect issue add their rules here.
#pragma once

#include "engine/framegraph/frame_needs.hpp"
#include "engine/scene/scene.hpp"

namespace vkw {

fg::FrameNeeds decide_frame_needs(const Scene& scene);

}  // namespace vkw
