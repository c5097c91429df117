// The declaration verbs of the frame graph, named after their Vulkan use, and the
// pure table that turns each into pipeline stages, access masks and an image layout.
// Barrier derivation needs nothing else, so layouts, stages and access masks are
// never written by hand in a pass.
#pragma once

#include <vulkan/vulkan.h>

#include <string>

namespace vkw::fg {

enum class PassKind : uint8_t { Graphics, Compute, Transfer };

enum class Use : uint8_t {
    // images
    SampledRead,            // texture() in a shader
    StorageImageRead,       // imageLoad
    StorageImageWrite,      // imageStore, previous contents discarded
    StorageImageReadWrite,  // imageLoad + imageStore / image atomics
    ColorAttachmentWrite,   // cleared or don't-care load
    ColorAttachmentBlend,   // loaded and blended into (read + write)
    DepthStencilWrite,      // depth/stencil test and write
    DepthStencilReadOnly,   // depth/stencil test without writes
    // buffers
    UniformBuffer,
    StorageBufferRead,
    StorageBufferWrite,
    StorageBufferReadWrite,
    VertexBuffer,
    IndexBuffer,
    IndirectBuffer,
    // both
    TransferSrc,
    TransferDst,
    // final state of an imported readback buffer: mapped and read on the CPU
    HostRead,
};

// One resource's state at one point of the frame: what the next barrier waits for
// (src) or makes available to (dst). Layout is UNDEFINED for buffers.
struct AccessState {
    VkPipelineStageFlags2 stages = VK_PIPELINE_STAGE_2_NONE;
    VkAccessFlags2 access = VK_ACCESS_2_NONE;
    VkImageLayout layout = VK_IMAGE_LAYOUT_UNDEFINED;

    bool operator==(const AccessState&) const = default;
};

bool is_write(Use use);
bool is_image_use(Use use);
bool is_buffer_use(Use use);
const char* use_name(Use use);

// Stages that touch the resource for a use in a pass of this kind. `shader_stages`
// overrides the default shader stage of graphics passes (fragment) for shader uses,
// e.g. a vertex shader that reads the water surface from a storage buffer.
AccessState access_state(Use use, PassKind kind, VkPipelineStageFlags2 shader_stages = 0,
                         bool is_depth_stencil_format = false);

// Usage flags a resource needs for a use (images: VkImageUsageFlags; buffers: VkBufferUsageFlags).
VkImageUsageFlags image_usage(Use use);
VkBufferUsageFlags buffer_usage(Use use);

// Printable names for dumps and error messages: "FRAGMENT_SHADER|COMPUTE_SHADER".
std::string stage_names(VkPipelineStageFlags2 stages);
std::string access_names(VkAccessFlags2 access);
const char* layout_name(VkImageLayout layout);

}  // namespace vkw::fg
