// The per-frame constants block (shaders/common/frame_constants.glsl, std140; its C++ mirror is
// generated) and the function that fills it from a scene.
#pragma once

#include "engine/scene/receiver_boxes.hpp"
#include "engine/scene/scene.hpp"
#include "engine/water/unresolved_slopes.hpp"

#include <glm/glm.hpp>
#include <shader_structs/common/shared_blocks.comp.hpp>

#include <cstdint>
#include <iterator>

namespace vkw {

// Solid angle of the sun's disk as the model fixes it (docs/model.md section 1), and the
// angular radius it corresponds to: 2 pi (1 - cos r) = 6.80e-5 sr for r = 0.2666 deg.
inline constexpr double kSunDiskSolidAngle = 6.80e-5;
inline constexpr double kSunDiskAngularRadiusDeg = 0.2666;

// The frame's constants (shaders/common/frame_constants.glsl, where each member is described), as
// generated from the SPIR-V of the shader that declares only the shared blocks.
using FrameConstants = glsl::shared_blocks_comp::FrameConstants;
static_assert(std::size(FrameConstants{}.unresolved_slopes) == kUnresolvedSlopeEntries);
static_assert(std::size(FrameConstants{}.receiver_box_min) == kReceiverBoxes);

FrameConstants make_frame_constants(const Scene& scene, uint32_t width, uint32_t height);

// Whether the camera's eye is in the water, the per-frame camera medium (height exactly at the
// level counts as above). The camera-medium split refines it per pixel where the near plane crosses
// the surface.
bool camera_eye_in_water(const Scene& scene);

}  // namespace vkw
