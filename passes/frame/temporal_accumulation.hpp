// Temporal accumulation across a sequence of frames (vkwater view --temporal, vkwater render
// --frames ... --temporal): each frame is rendered with the camera's image plane shifted by a
// sub-pixel jitter that cycles through the 16 strata centres of a 4 x 4 box filter, and blended
// into the colour accumulated over the frames before it, read where the pixel's surface point lay
// in the previous frame (the scene depth reprojected) and clamped to the range of this frame's
// 3 x 3 neighbourhood (shaders/frame/temporal_accumulate.comp). With the camera and the clock
// still and the clamp off, 16 frames give exactly the 16-sample box-filtered frame; with them
// running, the clamp bounds how long a stale history lingers. The layers (caustic, in-scatter)
// are not accumulated.
#pragma once

#include "engine/framegraph/frame_graph.hpp"

#include <glm/glm.hpp>

#include <cstdint>

namespace vkw::passes {

// The frames of one jitter cycle, and the usage the history image needs: read by the
// accumulation, then written by the copy of the frame's result.
inline constexpr uint32_t kTemporalJitterCycle = 16;
inline constexpr VkImageUsageFlags kTemporalHistoryUsage = VK_IMAGE_USAGE_STORAGE_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT;

// The sub-pixel offset of frame `index` of a sequence (pixels, each coordinate in (-0.5, 0.5)): the
// strata centres of a 4 x 4 box filter (PixelFilter, spp 16), visited in the order of the 4 x 4
// Bayer matrix, so that consecutive frames lie far apart and frames 4j to 4j + 3 cover the pixel's
// four quarters.
glm::dvec2 temporal_jitter(uint32_t index);

// The matrix from this frame's clip space to the previous frame's, both unjittered: a pixel's
// (NDC x, y, depth, 1) through it gives where its surface point lay in the previous image.
glm::dmat4 temporal_reprojection(const glm::dmat4& previous_view_proj, const glm::dmat4& view_proj);

struct TemporalInputs {
    // The accumulated colour of the frames before (RGBA32F, the output's size, kTemporalHistoryUsage),
    // owned by the caller; its state is the one the previous frame left (initial is ignored when
    // `first`: nothing is read from it).
    fg::ImportedImage history;
    bool first = true;          // no history: the frame goes through as it is
    glm::mat4 reprojection{1};  // temporal_reprojection
    bool camera_still = false;  // the same camera as the previous frame's: each pixel keeps its own history
    float blend = 1.0f;         // this frame's weight in (0, 1]
    bool clamp_history = true;
};

// Blends `colour` (the frame's HDR colour, RGBA32F) into the history and returns the accumulated
// colour (a new image of the same size), which is also copied into the history for the next frame.
// Reads keys::kSceneDepth.
fg::ImageHandle add_temporal_accumulation(fg::FrameGraph& graph, fg::ImageHandle colour, TemporalInputs inputs);

}  // namespace vkw::passes
