// Image and ReadbackBuffer (gpu_memory.hpp).
#include "gpu_memory.hpp"

#include "errors.hpp"
#include "host_device.hpp"

namespace embed_host {
namespace {

// The first memory type allowed by `type_bits` with all of `wanted`, or -1.
int find_memory_type(VkPhysicalDevice physical_device, uint32_t type_bits, VkMemoryPropertyFlags wanted) {
    VkPhysicalDeviceMemoryProperties properties;
    vkGetPhysicalDeviceMemoryProperties(physical_device, &properties);
    for (uint32_t i = 0; i < properties.memoryTypeCount; ++i) {
        if ((type_bits & (1u << i)) && (properties.memoryTypes[i].propertyFlags & wanted) == wanted) {
            return static_cast<int>(i);
        }
    }
    return -1;
}

VkDeviceMemory allocate(const HostVulkan& host, const VkMemoryRequirements& requirements,
                        VkMemoryPropertyFlags preferred, VkMemoryPropertyFlags required) {
    int type = find_memory_type(host.physical_device(), requirements.memoryTypeBits, preferred);
    if (type < 0) type = find_memory_type(host.physical_device(), requirements.memoryTypeBits, required);
    if (type < 0) throw HostError("no memory type fits the sample's image or buffer", kExitInternal);
    VkMemoryAllocateInfo info{};
    info.sType = VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO;
    info.allocationSize = requirements.size;
    info.memoryTypeIndex = static_cast<uint32_t>(type);
    VkDeviceMemory memory = VK_NULL_HANDLE;
    check(vkAllocateMemory(host.device(), &info, nullptr, &memory), "vkAllocateMemory");
    return memory;
}

}  // namespace

Image::Image(const HostVulkan& host, VkFormat image_format, uint32_t image_width, uint32_t image_height,
             VkImageUsageFlags usage, VkImageAspectFlags image_aspect)
    : format(image_format), width(image_width), height(image_height), aspect(image_aspect), device_(host.device()) {
    try {
        VkImageCreateInfo info{};
        info.sType = VK_STRUCTURE_TYPE_IMAGE_CREATE_INFO;
        info.imageType = VK_IMAGE_TYPE_2D;
        info.format = format;
        info.extent = {width, height, 1};
        info.mipLevels = 1;
        info.arrayLayers = 1;
        info.samples = VK_SAMPLE_COUNT_1_BIT;
        info.tiling = VK_IMAGE_TILING_OPTIMAL;
        info.usage = usage;
        info.sharingMode = VK_SHARING_MODE_EXCLUSIVE;
        info.initialLayout = VK_IMAGE_LAYOUT_UNDEFINED;
        check(vkCreateImage(device_, &info, nullptr, &image), "vkCreateImage");

        VkMemoryRequirements requirements;
        vkGetImageMemoryRequirements(device_, image, &requirements);
        memory_ = allocate(host, requirements, VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT, 0);
        check(vkBindImageMemory(device_, image, memory_, 0), "vkBindImageMemory");

        VkImageViewCreateInfo view_info{};
        view_info.sType = VK_STRUCTURE_TYPE_IMAGE_VIEW_CREATE_INFO;
        view_info.image = image;
        view_info.viewType = VK_IMAGE_VIEW_TYPE_2D;
        view_info.format = format;
        view_info.subresourceRange = {aspect, 0, 1, 0, 1};
        check(vkCreateImageView(device_, &view_info, nullptr, &view), "vkCreateImageView");
    } catch (...) {
        release();  // a constructor that throws runs no destructor
        throw;
    }
}

Image::~Image() { release(); }

void Image::release() {
    if (view) vkDestroyImageView(device_, view, nullptr);
    if (image) vkDestroyImage(device_, image, nullptr);
    if (memory_) vkFreeMemory(device_, memory_, nullptr);
    view = VK_NULL_HANDLE;
    image = VK_NULL_HANDLE;
    memory_ = VK_NULL_HANDLE;
}

ReadbackBuffer::ReadbackBuffer(const HostVulkan& host, VkDeviceSize buffer_size)
    : size(buffer_size), device_(host.device()) {
    try {
        VkBufferCreateInfo info{};
        info.sType = VK_STRUCTURE_TYPE_BUFFER_CREATE_INFO;
        info.size = size;
        info.usage = VK_BUFFER_USAGE_TRANSFER_DST_BIT;
        info.sharingMode = VK_SHARING_MODE_EXCLUSIVE;
        check(vkCreateBuffer(device_, &info, nullptr, &buffer), "vkCreateBuffer");

        VkMemoryRequirements requirements;
        vkGetBufferMemoryRequirements(device_, buffer, &requirements);
        // Cached memory reads fast on the CPU; coherent memory needs no vkInvalidateMappedMemoryRanges.
        const VkMemoryPropertyFlags required =
            VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT | VK_MEMORY_PROPERTY_HOST_COHERENT_BIT;
        memory_ = allocate(host, requirements, required | VK_MEMORY_PROPERTY_HOST_CACHED_BIT, required);
        check(vkBindBufferMemory(device_, buffer, memory_, 0), "vkBindBufferMemory");
        check(vkMapMemory(device_, memory_, 0, VK_WHOLE_SIZE, 0, &mapped_), "vkMapMemory");
    } catch (...) {
        release();
        throw;
    }
}

ReadbackBuffer::~ReadbackBuffer() { release(); }

void ReadbackBuffer::release() {
    if (buffer) vkDestroyBuffer(device_, buffer, nullptr);
    if (memory_) vkFreeMemory(device_, memory_, nullptr);  // unmaps it
    buffer = VK_NULL_HANDLE;
    memory_ = VK_NULL_HANDLE;
}

}  // namespace embed_host
