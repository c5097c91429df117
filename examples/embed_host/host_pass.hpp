// The host's own rendering, before vkwater's: clears its colour and depth targets and draws the box.
// What it leaves the targets in is what the host then tells vkwater (Target::before, as_target).
#pragma once

#include "box.hpp"
#include "gpu_memory.hpp"

#include <vkwater/world.hpp>

#include <vulkan/vulkan.h>

namespace embed_host {

// The states the host's pass leaves its targets in.
inline constexpr vkwater::ImageState kColorAfterHostPass{VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL,
                                                         VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT,
                                                         VK_ACCESS_2_COLOR_ATTACHMENT_WRITE_BIT};
inline constexpr vkwater::ImageState kDepthAfterHostPass{
    VK_IMAGE_LAYOUT_DEPTH_STENCIL_ATTACHMENT_OPTIMAL,
    VK_PIPELINE_STAGE_2_EARLY_FRAGMENT_TESTS_BIT | VK_PIPELINE_STAGE_2_LATE_FRAGMENT_TESTS_BIT,
    VK_ACCESS_2_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT};

// Records the pass: the targets' old contents are discarded, colour cleared to (0, 0, 0, 1) and depth
// to 0 (reverse Z: the far plane, where the host drew nothing, as vkwater::Frame asks). `color_last`
// and `depth_last`: the stages and accesses of the targets' last use (the previous frame's), which
// the clears must wait for.
void record_host_pass(VkCommandBuffer cmd, const Image& color, const Image& depth,
                      const vkwater::ImageState& color_last, const vkwater::ImageState& depth_last,
                      const BoxPipeline& box, const vkwater::CameraMatrices& camera, const Mat4& box_model);

// A host image as vkwater takes it: the image, its view, format and size, and the states it is in
// before vkwater's commands and must be left in after them.
vkwater::Target as_target(const Image& image, const vkwater::ImageState& before, const vkwater::ImageState& after);

}  // namespace embed_host
