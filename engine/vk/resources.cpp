#include "engine/vk/resources.hpp"

#include "engine/core/errors.hpp"
#include "engine/vk/check.hpp"
#include "engine/vk/context.hpp"

#include <utility>

namespace vkw {

DeviceMemory::DeviceMemory(const Context& context, VkDeviceSize size, uint32_t type_bits,
                           VkMemoryPropertyFlags properties, const std::string& name)
    : device_(context.device()), allocator_(context.allocator()), size_(size) {
    VkMemoryAllocateInfo info{VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO};
    info.allocationSize = size;
    info.memoryTypeIndex = context.find_memory_type(type_bits, properties);
    VKW_CHECK(vkAllocateMemory(device_, &info, allocator_, &memory_), "memory of '" + name + "'");
    context.count_memory_allocation();
    context.set_name(memory_, VK_OBJECT_TYPE_DEVICE_MEMORY, name);
    if (properties & VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT) {
        VKW_CHECK(vkMapMemory(device_, memory_, 0, VK_WHOLE_SIZE, 0, &mapped_), "mapping '" + name + "'");
    }
}

DeviceMemory::~DeviceMemory() { reset(); }

DeviceMemory::DeviceMemory(DeviceMemory&& other) noexcept { *this = std::move(other); }

DeviceMemory& DeviceMemory::operator=(DeviceMemory&& other) noexcept {
    if (this != &other) {
        reset();
        device_ = std::exchange(other.device_, VK_NULL_HANDLE);
        allocator_ = std::exchange(other.allocator_, nullptr);
        memory_ = std::exchange(other.memory_, VK_NULL_HANDLE);
        size_ = std::exchange(other.size_, 0);
        mapped_ = std::exchange(other.mapped_, nullptr);
    }
    return *this;
}

void DeviceMemory::reset() {
    if (memory_) vkFreeMemory(device_, memory_, allocator_);  // unmaps implicitly
    memory_ = VK_NULL_HANDLE;
    mapped_ = nullptr;
}

Buffer Buffer::create_unbound(const Context& context, const BufferDesc& desc, const std::string& name) {
    Buffer buffer;
    buffer.device_ = context.device();
    buffer.allocator_ = context.allocator();
    buffer.size_ = desc.size;
    VkBufferCreateInfo info{VK_STRUCTURE_TYPE_BUFFER_CREATE_INFO};
    info.size = desc.size;
    info.usage = desc.usage;
    info.sharingMode = VK_SHARING_MODE_EXCLUSIVE;
    VKW_CHECK(vkCreateBuffer(buffer.device_, &info, buffer.allocator_, &buffer.buffer_), "buffer '" + name + "'");
    context.set_name(buffer.buffer_, VK_OBJECT_TYPE_BUFFER, name);
    return buffer;
}

Buffer::Buffer(const Context& context, const BufferDesc& desc, const std::string& name) {
    *this = create_unbound(context, desc, name);
    const VkMemoryRequirements requirements = memory_requirements();
    const VkMemoryPropertyFlags properties =
        desc.host_visible ? VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT | VK_MEMORY_PROPERTY_HOST_COHERENT_BIT
                          : VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT;
    memory_ = DeviceMemory(context, requirements.size, requirements.memoryTypeBits, properties, name);
    bind(memory_.handle(), 0, name);
}

VkMemoryRequirements Buffer::memory_requirements() const {
    VkMemoryRequirements requirements;
    vkGetBufferMemoryRequirements(device_, buffer_, &requirements);
    return requirements;
}

void Buffer::bind(VkDeviceMemory memory, VkDeviceSize offset, const std::string& name) {
    VKW_CHECK(vkBindBufferMemory(device_, buffer_, memory, offset), "buffer '" + name + "'");
}

Buffer::~Buffer() { reset(); }

Buffer::Buffer(Buffer&& other) noexcept { *this = std::move(other); }

Buffer& Buffer::operator=(Buffer&& other) noexcept {
    if (this != &other) {
        reset();
        device_ = std::exchange(other.device_, VK_NULL_HANDLE);
        allocator_ = std::exchange(other.allocator_, nullptr);
        buffer_ = std::exchange(other.buffer_, VK_NULL_HANDLE);
        size_ = std::exchange(other.size_, 0);
        memory_ = std::move(other.memory_);
    }
    return *this;
}

void Buffer::reset() {
    if (buffer_) vkDestroyBuffer(device_, buffer_, allocator_);
    buffer_ = VK_NULL_HANDLE;
    memory_ = DeviceMemory();
}

Image Image::create_unbound(const Context& context, const ImageDesc& desc, const std::string& name) {
    Image image;
    image.context_ = &context;
    image.device_ = context.device();
    image.allocator_ = context.allocator();
    image.desc_ = desc;
    VkImageCreateInfo info{VK_STRUCTURE_TYPE_IMAGE_CREATE_INFO};
    info.imageType = VK_IMAGE_TYPE_2D;
    info.format = desc.format;
    info.extent = {desc.width, desc.height, 1};
    info.mipLevels = desc.mip_levels;
    info.arrayLayers = 1;
    info.samples = VK_SAMPLE_COUNT_1_BIT;
    info.tiling = VK_IMAGE_TILING_OPTIMAL;
    info.usage = desc.usage;
    info.sharingMode = VK_SHARING_MODE_EXCLUSIVE;
    info.initialLayout = VK_IMAGE_LAYOUT_UNDEFINED;
    VKW_CHECK(vkCreateImage(image.device_, &info, image.allocator_, &image.image_), "image '" + name + "'");
    context.set_name(image.image_, VK_OBJECT_TYPE_IMAGE, name);
    return image;
}

Image::Image(const Context& context, const ImageDesc& desc, const std::string& name) {
    *this = create_unbound(context, desc, name);
    const VkMemoryRequirements requirements = memory_requirements();
    own_memory_ = DeviceMemory(context, requirements.size, requirements.memoryTypeBits,
                               VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT, name);
    bind(context, own_memory_.handle(), 0, name);
}

VkMemoryRequirements Image::memory_requirements() const {
    VkMemoryRequirements requirements;
    vkGetImageMemoryRequirements(device_, image_, &requirements);
    return requirements;
}

void Image::bind(const Context& context, VkDeviceMemory memory, VkDeviceSize offset, const std::string& name) {
    VKW_CHECK(vkBindImageMemory(device_, image_, memory, offset), "image '" + name + "'");
    VkImageViewCreateInfo view_info{VK_STRUCTURE_TYPE_IMAGE_VIEW_CREATE_INFO};
    view_info.image = image_;
    view_info.viewType = VK_IMAGE_VIEW_TYPE_2D;
    view_info.format = desc_.format;
    // A depth-stencil view used for sampling may only name one aspect; vkwater samples depth.
    VkImageAspectFlags view_aspect = aspect();
    if (format_is_depth(desc_.format)) view_aspect = VK_IMAGE_ASPECT_DEPTH_BIT;
    view_info.subresourceRange = {view_aspect, 0, desc_.mip_levels, 0, 1};
    VKW_CHECK(vkCreateImageView(device_, &view_info, allocator_, &view_), "view of image '" + name + "'");
    context.set_name(view_, VK_OBJECT_TYPE_IMAGE_VIEW, name);
}

VkImageAspectFlags Image::aspect() const { return format_aspect(desc_.format); }

Sampler::Sampler(const Context& context, const VkSamplerCreateInfo& info, const std::string& name)
    : device_(context.device()), allocator_(context.allocator()) {
    VKW_CHECK(vkCreateSampler(device_, &info, allocator_, &sampler_), "sampler '" + name + "'");
    context.set_name(sampler_, VK_OBJECT_TYPE_SAMPLER, name);
}

Sampler::~Sampler() { reset(); }

Sampler::Sampler(Sampler&& other) noexcept { *this = std::move(other); }

Sampler& Sampler::operator=(Sampler&& other) noexcept {
    if (this != &other) {
        reset();
        device_ = other.device_;
        allocator_ = other.allocator_;
        sampler_ = other.sampler_;
        other.sampler_ = VK_NULL_HANDLE;
    }
    return *this;
}

void Sampler::reset() {
    if (sampler_) vkDestroySampler(device_, sampler_, allocator_);
    sampler_ = VK_NULL_HANDLE;
}

Image::~Image() { reset(); }

Image::Image(Image&& other) noexcept { *this = std::move(other); }

Image& Image::operator=(Image&& other) noexcept {
    if (this != &other) {
        reset();
        context_ = std::exchange(other.context_, nullptr);
        device_ = std::exchange(other.device_, VK_NULL_HANDLE);
        allocator_ = std::exchange(other.allocator_, nullptr);
        image_ = std::exchange(other.image_, VK_NULL_HANDLE);
        view_ = std::exchange(other.view_, VK_NULL_HANDLE);
        desc_ = other.desc_;
        own_memory_ = std::move(other.own_memory_);
    }
    return *this;
}

void Image::reset() {
    if (context_) {
        context_->forget_name(view_, VK_OBJECT_TYPE_IMAGE_VIEW);
        context_->forget_name(image_, VK_OBJECT_TYPE_IMAGE);
    }
    if (view_) vkDestroyImageView(device_, view_, allocator_);
    if (image_) vkDestroyImage(device_, image_, allocator_);
    view_ = VK_NULL_HANDLE;
    image_ = VK_NULL_HANDLE;
    own_memory_ = DeviceMemory();
}

bool format_is_depth(VkFormat format) {
    switch (format) {
        case VK_FORMAT_D16_UNORM:
        case VK_FORMAT_D32_SFLOAT:
        case VK_FORMAT_D24_UNORM_S8_UINT:
        case VK_FORMAT_D32_SFLOAT_S8_UINT:
        case VK_FORMAT_X8_D24_UNORM_PACK32: return true;
        default: return false;
    }
}

bool format_has_stencil(VkFormat format) {
    return format == VK_FORMAT_D24_UNORM_S8_UINT || format == VK_FORMAT_D32_SFLOAT_S8_UINT ||
           format == VK_FORMAT_S8_UINT;
}

VkImageAspectFlags format_aspect(VkFormat format) {
    VkImageAspectFlags aspect = 0;
    if (format_is_depth(format)) aspect |= VK_IMAGE_ASPECT_DEPTH_BIT;
    if (format_has_stencil(format)) aspect |= VK_IMAGE_ASPECT_STENCIL_BIT;
    return aspect != 0 ? aspect : VkImageAspectFlags{VK_IMAGE_ASPECT_COLOR_BIT};
}

bool format_is_float_color(VkFormat format) {
    switch (format) {
        case VK_FORMAT_R32_SFLOAT:
        case VK_FORMAT_R32G32_SFLOAT:
        case VK_FORMAT_R32G32B32A32_SFLOAT:
        case VK_FORMAT_R16_SFLOAT:
        case VK_FORMAT_R16G16_SFLOAT:
        case VK_FORMAT_R16G16B16A16_SFLOAT: return true;
        default: return false;
    }
}

uint32_t format_texel_bytes(VkFormat format) {
    switch (format) {
        case VK_FORMAT_R8G8B8A8_UNORM:
        case VK_FORMAT_B8G8R8A8_UNORM:
        case VK_FORMAT_R8G8B8A8_SRGB:
        case VK_FORMAT_B8G8R8A8_SRGB:
        case VK_FORMAT_R32_SFLOAT:
        case VK_FORMAT_R32_UINT:
        case VK_FORMAT_R16G16_SFLOAT:
        case VK_FORMAT_D32_SFLOAT:
        case VK_FORMAT_D24_UNORM_S8_UINT: return 4;
        case VK_FORMAT_R16_SFLOAT: return 2;
        case VK_FORMAT_R8_UNORM: return 1;
        case VK_FORMAT_R32G32_SFLOAT:
        case VK_FORMAT_R16G16B16A16_SFLOAT:
        case VK_FORMAT_D32_SFLOAT_S8_UINT: return 8;
        case VK_FORMAT_R32G32B32A32_SFLOAT: return 16;
        default: throw InternalError(std::string("format_texel_bytes: unsupported format ") + format_name(format));
    }
}

const char* format_name(VkFormat format) {
    switch (format) {
        case VK_FORMAT_R8G8B8A8_UNORM: return "RGBA8_UNORM";
        case VK_FORMAT_B8G8R8A8_UNORM: return "BGRA8_UNORM";
        case VK_FORMAT_R8G8B8A8_SRGB: return "RGBA8_SRGB";
        case VK_FORMAT_B8G8R8A8_SRGB: return "BGRA8_SRGB";
        case VK_FORMAT_R32_SFLOAT: return "R32F";
        case VK_FORMAT_R8_UNORM: return "R8_UNORM";
        case VK_FORMAT_R32_UINT: return "R32_UINT";
        case VK_FORMAT_R32G32_SFLOAT: return "RG32F";
        case VK_FORMAT_R16G16_SFLOAT: return "RG16F";
        case VK_FORMAT_R16_SFLOAT: return "R16F";
        case VK_FORMAT_R16G16B16A16_SFLOAT: return "RGBA16F";
        case VK_FORMAT_R32G32B32A32_SFLOAT: return "RGBA32F";
        case VK_FORMAT_D32_SFLOAT: return "D32F";
        case VK_FORMAT_D24_UNORM_S8_UINT: return "D24S8";
        case VK_FORMAT_D32_SFLOAT_S8_UINT: return "D32FS8";
        default: return "format?";
    }
}

}  // namespace vkw
