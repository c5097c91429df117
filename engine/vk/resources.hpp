// Move-only owners of Vulkan buffers, images and device memory. The frame graph
// creates most of them; tests and the CLI use them for uploads and readbacks.
#pragma once

#include <vulkan/vulkan.h>

#include <string>

namespace vkw {

class Context;

class DeviceMemory {
public:
    DeviceMemory() = default;
    DeviceMemory(const Context& context, VkDeviceSize size, uint32_t type_bits, VkMemoryPropertyFlags properties,
                 const std::string& name);
    ~DeviceMemory();
    DeviceMemory(DeviceMemory&& other) noexcept;
    DeviceMemory& operator=(DeviceMemory&& other) noexcept;

    VkDeviceMemory handle() const { return memory_; }
    VkDeviceSize size() const { return size_; }
    void* mapped() const { return mapped_; }  // non-null when host-visible

private:
    void reset();
    VkDevice device_ = VK_NULL_HANDLE;
    // Context::allocator(), kept because objects must be freed with the callbacks that made them.
    const VkAllocationCallbacks* allocator_ = nullptr;
    VkDeviceMemory memory_ = VK_NULL_HANDLE;
    VkDeviceSize size_ = 0;
    void* mapped_ = nullptr;
};

struct BufferDesc {
    VkDeviceSize size = 0;
    VkBufferUsageFlags usage = 0;
    bool host_visible = false;  // mapped persistently; for uploads and readbacks
};

class Buffer {
public:
    Buffer() = default;
    // Creates the buffer with its own memory.
    Buffer(const Context& context, const BufferDesc& desc, const std::string& name);
    // Two-step creation for aliasing (device-local only): create, query, bind.
    static Buffer create_unbound(const Context& context, const BufferDesc& desc, const std::string& name);
    VkMemoryRequirements memory_requirements() const;
    void bind(VkDeviceMemory memory, VkDeviceSize offset, const std::string& name);
    ~Buffer();
    Buffer(Buffer&& other) noexcept;
    Buffer& operator=(Buffer&& other) noexcept;

    VkBuffer handle() const { return buffer_; }
    VkDeviceSize size() const { return size_; }
    void* mapped() const { return memory_.mapped(); }

private:
    void reset();
    VkDevice device_ = VK_NULL_HANDLE;
    // Context::allocator(), kept because objects must be freed with the callbacks that made them.
    const VkAllocationCallbacks* allocator_ = nullptr;
    VkBuffer buffer_ = VK_NULL_HANDLE;
    VkDeviceSize size_ = 0;
    DeviceMemory memory_;
};

struct ImageDesc {
    uint32_t width = 0;
    uint32_t height = 0;
    VkFormat format = VK_FORMAT_UNDEFINED;
    VkImageUsageFlags usage = 0;
    uint32_t mip_levels = 1;  // the view covers them all
};

// An image and its one view. Either owns its memory or is bound into memory owned
// by someone else (the frame graph's transient heap, where lifetimes alias).
class Image {
public:
    Image() = default;
    Image(const Context& context, const ImageDesc& desc, const std::string& name);  // own memory
    ~Image();
    Image(Image&& other) noexcept;
    Image& operator=(Image&& other) noexcept;

    // Two-step creation for aliasing: create unbound, query requirements, bind, then make the view.
    static Image create_unbound(const Context& context, const ImageDesc& desc, const std::string& name);
    VkMemoryRequirements memory_requirements() const;
    void bind(const Context& context, VkDeviceMemory memory, VkDeviceSize offset, const std::string& name);

    VkImage handle() const { return image_; }
    VkImageView view() const { return view_; }
    const ImageDesc& desc() const { return desc_; }
    VkImageAspectFlags aspect() const;

private:
    void reset();
    const Context* context_ = nullptr;  // to drop the names with the objects (Context::forget_name)
    VkDevice device_ = VK_NULL_HANDLE;
    // Context::allocator(), kept because objects must be freed with the callbacks that made them.
    const VkAllocationCallbacks* allocator_ = nullptr;
    VkImage image_ = VK_NULL_HANDLE;
    VkImageView view_ = VK_NULL_HANDLE;
    ImageDesc desc_;
    DeviceMemory own_memory_;
};

// A sampler, owned (the frame graph's executor keeps the shared linear and nearest ones).
class Sampler {
public:
    Sampler() = default;
    Sampler(const Context& context, const VkSamplerCreateInfo& info, const std::string& name);
    ~Sampler();
    Sampler(Sampler&& other) noexcept;
    Sampler& operator=(Sampler&& other) noexcept;

    VkSampler handle() const { return sampler_; }

private:
    void reset();
    VkDevice device_ = VK_NULL_HANDLE;
    // Context::allocator(), kept because objects must be freed with the callbacks that made them.
    const VkAllocationCallbacks* allocator_ = nullptr;
    VkSampler sampler_ = VK_NULL_HANDLE;
};

// Aspect bits of a format: depth and/or stencil for depth formats, colour otherwise.
VkImageAspectFlags format_aspect(VkFormat format);
bool format_has_stencil(VkFormat format);
bool format_is_depth(VkFormat format);
// 32-bit or 16-bit float colour formats, which the finite-check mode scans.
bool format_is_float_color(VkFormat format);
uint32_t format_texel_bytes(VkFormat format);
const char* format_name(VkFormat format);

}  // namespace vkw
