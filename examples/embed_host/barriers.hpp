// The host's barriers, written with vkwater's own ImageState {layout, stages, access}: the same
// triple that a vkwater::Target's `before` and `after` are given in, so that the states the host
// leaves its images in and those it hands to vkwater are visibly the same values.
#pragma once

#include <vkwater/world.hpp>

#include <vulkan/vulkan.h>

namespace embed_host {

// One image barrier (synchronization2) from `from` to `to` over the whole image. `from.layout`
// UNDEFINED discards the contents (the host clears them anyway) but still waits for `from.stages`.
void transition(VkCommandBuffer cmd, VkImage image, VkImageAspectFlags aspect, const vkwater::ImageState& from,
                const vkwater::ImageState& to);

// Makes the copies into readback buffers visible to the host: a fence alone does not (its
// dependency covers device accesses only).
void copies_to_host(VkCommandBuffer cmd);

}  // namespace embed_host
