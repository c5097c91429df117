// The window's display transform: the linear HDR frame times the camera's exposure, the ACES
// filmic curve (Narkowicz fit) and the sRGB encoding of engine/image/tone_curve.hpp (the chain
// of the --png preview), one HDR texel per pixel into the swapchain image. For a UNORM
// swapchain the shader encodes sRGB; for an _SRGB one the hardware does. Pixels with a
// non-finite R, G or B show magenta, as in the preview. Shader: shaders/present/present_tonemap.frag.
#pragma once

#include "engine/framegraph/frame_graph.hpp"

namespace vkw::passes {

// Read when the pass records, so that a new exposure needs no new graph.
struct PresentTonemapSettings {
    float exposure = 1.0f;    // linear scale on radiance, > 0
    bool encode_srgb = true;  // false when the target's format encodes sRGB itself
};

// `hdr` and `target` have the same size. Returns the target's new version.
[[nodiscard]] fg::ImageHandle add_present_tonemap_pass(fg::FrameGraph& graph, fg::ImageHandle hdr,
                                                       fg::ImageHandle target, const PresentTonemapSettings* settings);

}  // namespace vkw::passes
