// A few world-space boxes that together hold every receiver mesh: the water's shader skips a
// ray's lookups in the scene views where the ray meets none of them (water/scene_lookup.glsl),
// since the views hold the receiver meshes alone. Each receiver gets its own box while they fit;
// the rest share the last one, the box around all of them, so the boxes stay conservative for any
// number of receivers.
#pragma once

#include "engine/scene/scene.hpp"

#include <glm/glm.hpp>

#include <array>
#include <cstddef>

namespace vkw {

// As many as the frame constants carry (shaders/common/frame_constants.glsl).
inline constexpr std::size_t kReceiverBoxes = 8;

struct ReceiverBoxes {
    std::size_t count = 0;  // how many of the boxes are used; 0 without receivers
    std::array<glm::dvec3, kReceiverBoxes> lo{}, hi{};
};

// Each mesh's bounds, widened by a margin that covers the fp32 rounding of the shader's ray-box test
// (1e-5 of the box's largest coordinate, and at least 0.1 mm).
ReceiverBoxes receiver_boxes(const Scene& scene);

}  // namespace vkw
