// record_host_pass and as_target (host_pass.hpp).
#include "host_pass.hpp"

#include "barriers.hpp"

namespace embed_host {

void record_host_pass(VkCommandBuffer cmd, const Image& color, const Image& depth,
                      const vkwater::ImageState& color_last, const vkwater::ImageState& depth_last,
                      const BoxPipeline& box, const vkwater::CameraMatrices& camera, const Mat4& box_model) {
    // From UNDEFINED: last frame's contents are not needed, but its reads and writes must be over.
    transition(cmd, color.image, color.aspect, {VK_IMAGE_LAYOUT_UNDEFINED, color_last.stages, color_last.access},
               kColorAfterHostPass);
    transition(cmd, depth.image, depth.aspect, {VK_IMAGE_LAYOUT_UNDEFINED, depth_last.stages, depth_last.access},
               {kDepthAfterHostPass.layout, kDepthAfterHostPass.stages,
                VK_ACCESS_2_DEPTH_STENCIL_ATTACHMENT_READ_BIT | VK_ACCESS_2_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT});

    VkRenderingAttachmentInfo color_attachment{};
    color_attachment.sType = VK_STRUCTURE_TYPE_RENDERING_ATTACHMENT_INFO;
    color_attachment.imageView = color.view;
    color_attachment.imageLayout = kColorAfterHostPass.layout;
    color_attachment.loadOp = VK_ATTACHMENT_LOAD_OP_CLEAR;
    color_attachment.storeOp = VK_ATTACHMENT_STORE_OP_STORE;
    color_attachment.clearValue.color = {{0.0f, 0.0f, 0.0f, 1.0f}};
    VkRenderingAttachmentInfo depth_attachment{};
    depth_attachment.sType = VK_STRUCTURE_TYPE_RENDERING_ATTACHMENT_INFO;
    depth_attachment.imageView = depth.view;
    depth_attachment.imageLayout = kDepthAfterHostPass.layout;
    depth_attachment.loadOp = VK_ATTACHMENT_LOAD_OP_CLEAR;
    depth_attachment.storeOp = VK_ATTACHMENT_STORE_OP_STORE;  // vkwater tests against it
    depth_attachment.clearValue.depthStencil = {0.0f, 0};

    VkRenderingInfo rendering{};
    rendering.sType = VK_STRUCTURE_TYPE_RENDERING_INFO;
    rendering.renderArea = {{0, 0}, {color.width, color.height}};
    rendering.layerCount = 1;
    rendering.colorAttachmentCount = 1;
    rendering.pColorAttachments = &color_attachment;
    rendering.pDepthAttachment = &depth_attachment;
    vkCmdBeginRendering(cmd, &rendering);
    box.draw(cmd, camera, box_model, color.width, color.height);
    vkCmdEndRendering(cmd);
}

vkwater::Target as_target(const Image& image, const vkwater::ImageState& before, const vkwater::ImageState& after) {
    vkwater::Target target;
    target.image = image.image;
    target.view = image.view;
    target.format = image.format;
    target.width = image.width;
    target.height = image.height;
    target.before = before;
    target.after = after;
    return target;
}

}  // namespace embed_host
