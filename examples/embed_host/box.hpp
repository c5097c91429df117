// The host's own geometry: an orange cube drawn with vkwater's camera matrices into the host's
// colour and depth targets (reverse Z), before vkwater records the water around and in front of it.
#pragma once

#include <vkwater/world.hpp>

#include <vulkan/vulkan.h>

#include <array>

namespace embed_host {

using Mat4 = std::array<float, 16>;  // column-major, as vkwater::CameraMatrices

Mat4 multiply(const Mat4& a, const Mat4& b);  // a * b

// The sample's box: a cube of `size` metres centred a `fraction` of the way from the camera to the
// point it looks at, so that it is well inside the view and nearer than the water behind it.
Mat4 box_model(const vkwater::Camera& camera, float size = 0.6f, double fraction = 0.35);

class BoxPipeline {
public:
    // For dynamic rendering into these formats (no render pass object).
    BoxPipeline(VkDevice device, VkFormat color_format, VkFormat depth_format);
    ~BoxPipeline();
    BoxPipeline(const BoxPipeline&) = delete;
    BoxPipeline& operator=(const BoxPipeline&) = delete;

    // Inside the host's rendering over a width x height target. The viewport is the standard
    // (0, 0, width, height): vkwater's projection already carries the y flip (World::matrices).
    void draw(VkCommandBuffer cmd, const vkwater::CameraMatrices& camera, const Mat4& model, uint32_t width,
              uint32_t height) const;

private:
    void release();
    VkDevice device_;
    VkPipelineLayout layout_ = VK_NULL_HANDLE;
    VkPipeline pipeline_ = VK_NULL_HANDLE;
};

}  // namespace embed_host
