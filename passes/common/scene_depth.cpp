// scene_depth_attachment (scene_depth.hpp).
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

}  // namespace vkw::passes
