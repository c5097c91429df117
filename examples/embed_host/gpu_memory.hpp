// The sample's own images and buffers, each with memory of its own (a real host suballocates from
// an allocator such as VMA; vkwater does not care where a target's memory comes from).
#pragma once

#include <vulkan/vulkan.h>

#include <cstdint>

namespace embed_host {

class HostVulkan;

// A 2D image with one mip level and layer, and its view over `aspect`: what a vkwater::Target names.
class Image {
public:
    Image(const HostVulkan& host, VkFormat format, uint32_t width, uint32_t height, VkImageUsageFlags usage,
          VkImageAspectFlags aspect);
    ~Image();
    Image(const Image&) = delete;
    Image& operator=(const Image&) = delete;

    VkImage image = VK_NULL_HANDLE;
    VkImageView view = VK_NULL_HANDLE;
    VkFormat format;
    uint32_t width, height;
    VkImageAspectFlags aspect;

private:
    void release();
    VkDevice device_;
    VkDeviceMemory memory_ = VK_NULL_HANDLE;
};

// A host-visible, persistently mapped buffer that the GPU copies an image into for the CPU to read.
class ReadbackBuffer {
public:
    ReadbackBuffer(const HostVulkan& host, VkDeviceSize size);
    ~ReadbackBuffer();
    ReadbackBuffer(const ReadbackBuffer&) = delete;
    ReadbackBuffer& operator=(const ReadbackBuffer&) = delete;

    VkBuffer buffer = VK_NULL_HANDLE;
    VkDeviceSize size;
    const void* data() const { return mapped_; }

private:
    void release();
    VkDevice device_;
    VkDeviceMemory memory_ = VK_NULL_HANDLE;
    void* mapped_ = nullptr;
};

}  // namespace embed_host
