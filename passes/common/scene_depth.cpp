// scene_depth_attachment and hdr_colour_attachment (scene_depth.hpp).
#include "passes/common/scene_depth.hpp"

#include "passes/common/frame_keys.hpp"

namespace vkw::passes {

fg::ImageHandle scene_depth_attachment(fg::PassBuilder& builder, const fg::Blackboard& blackboard) {
    if (blackboard.has(keys::kSceneDepth)) {
        return builder.depth_stencil_attachment(blackboard.get(keys::kSceneDepth), fg::LoadOp::Load);
    }
    const fg::ImageHandle created = builder.create_image("scene depth", {VK_FORMAT_D32_SFLOAT});
    return builder.depth_stencil_attachment(created, fg::LoadOp::Clear, {.depth = 0.0f});
}

fg::ImageHandle hdr_colour_attachment(fg::PassBuilder& builder, const fg::Blackboard& blackboard) {
    if (blackboard.has(keys::kHdrColor))
        return builder.color_attachment(blackboard.get(keys::kHdrColor), fg::LoadOp::Load);
    // 32-bit float: the sun's disk alone exceeds half-float range once E_s > 4.4 W m^-2
    // (docs/model.md section 1).
    const fg::ImageHandle created = builder.create_image("hdr colour", {VK_FORMAT_R32G32B32A32_SFLOAT});
    // Cleared to 0 rather than left undefined: the pixels the sky fills later are then finite in
    // between, as the frame's finite check wants of every pass's output.
    return builder.color_attachment(created, fg::LoadOp::Clear);
}

}  // namespace vkw::passes
