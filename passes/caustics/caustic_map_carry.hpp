// The light-space caustic map carried from the first sub-frame of a supersampled frame to the
// others (passes/frame/supersampled_frame.hpp). The map depends on the sun and the waves, not on
// where the camera's image plane sits within a pixel, so one map serves every sub-frame: the first
// copies the map it makes into an image that outlives its graph, and the others import that image
// in place of the passes that make it (the flux clear, the photons and the resolve).
#pragma once

#include "engine/framegraph/frame_graph.hpp"

namespace vkw::passes {

// The usage the kept image needs: the copy's destination, then sampled like the map itself.
inline constexpr VkImageUsageFlags kKeptCausticMapUsage = VK_IMAGE_USAGE_TRANSFER_DST_BIT | VK_IMAGE_USAGE_SAMPLED_BIT;

// `kept` is an image of the map's size and format with kKeptCausticMapUsage, owned by the caller
// (the renderer keeps one); its states are set here.
//
// Adds the pass that copies the map's `irradiance` into `kept` (the first sub-frame). The graph
// leaves `kept` in the state import_kept_caustic_map expects.
void add_caustic_map_keep_pass(fg::FrameGraph& graph, fg::ImageHandle irradiance, const fg::ImportedImage& kept);

// The kept map, imported in the state the keep pass left it in (the later sub-frames).
fg::ImageHandle import_kept_caustic_map(fg::FrameGraph& graph, const fg::ImportedImage& kept);

}  // namespace vkw::passes
