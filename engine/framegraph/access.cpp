#include "engine/framegraph/access.hpp"

#include "engine/core/errors.hpp"

#include <utility>

namespace vkw::fg {

bool is_write(Use use) {
    switch (use) {
        case Use::StorageImageWrite:
        case Use::StorageImageReadWrite:
        case Use::ColorAttachmentWrite:
        case Use::ColorAttachmentBlend:
        case Use::DepthStencilWrite:
        case Use::StorageBufferWrite:
        case Use::StorageBufferReadWrite:
        case Use::TransferDst: return true;
        default: return false;
    }
}

bool is_image_use(Use use) {
    switch (use) {
        case Use::SampledRead:
        case Use::StorageImageRead:
        case Use::StorageImageWrite:
        case Use::StorageImageReadWrite:
        case Use::ColorAttachmentWrite:
        case Use::ColorAttachmentBlend:
        case Use::DepthStencilWrite:
        case Use::DepthStencilReadOnly:
        case Use::TransferSrc:
        case Use::TransferDst: return true;
        default: return false;
    }
}

bool is_buffer_use(Use use) {
    switch (use) {
        case Use::UniformBuffer:
        case Use::StorageBufferRead:
        case Use::StorageBufferWrite:
        case Use::StorageBufferReadWrite:
        case Use::VertexBuffer:
        case Use::IndexBuffer:
        case Use::IndirectBuffer:
        case Use::TransferSrc:
        case Use::TransferDst:
        case Use::HostRead: return true;
        default: return false;
    }
}

const char* use_name(Use use) {
    switch (use) {
        case Use::SampledRead: return "sampled read";
        case Use::StorageImageRead: return "storage image read";
        case Use::StorageImageWrite: return "storage image write";
        case Use::StorageImageReadWrite: return "storage image read/write";
        case Use::ColorAttachmentWrite: return "colour attachment";
        case Use::ColorAttachmentBlend: return "colour attachment (blend)";
        case Use::DepthStencilWrite: return "depth-stencil attachment";
        case Use::DepthStencilReadOnly: return "depth-stencil attachment (read-only)";
        case Use::UniformBuffer: return "uniform buffer";
        case Use::StorageBufferRead: return "storage buffer read";
        case Use::StorageBufferWrite: return "storage buffer write";
        case Use::StorageBufferReadWrite: return "storage buffer read/write";
        case Use::VertexBuffer: return "vertex buffer";
        case Use::IndexBuffer: return "index buffer";
        case Use::IndirectBuffer: return "indirect buffer";
        case Use::TransferSrc: return "transfer source";
        case Use::TransferDst: return "transfer destination";
        case Use::HostRead: return "host read";
    }
    return "?";
}

AccessState access_state(Use use, PassKind kind, VkPipelineStageFlags2 shader_stages, bool depth_stencil_format) {
    VkPipelineStageFlags2 shader = shader_stages;
    if (shader == 0) {
        shader = kind == PassKind::Compute ? VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT
                                           : VK_PIPELINE_STAGE_2_FRAGMENT_SHADER_BIT;
    }
    constexpr VkPipelineStageFlags2 kFragmentTests =
        VK_PIPELINE_STAGE_2_EARLY_FRAGMENT_TESTS_BIT | VK_PIPELINE_STAGE_2_LATE_FRAGMENT_TESTS_BIT;
    switch (use) {
        case Use::SampledRead:
            return {shader, VK_ACCESS_2_SHADER_SAMPLED_READ_BIT,
                    depth_stencil_format ? VK_IMAGE_LAYOUT_DEPTH_STENCIL_READ_ONLY_OPTIMAL
                                         : VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL};
        case Use::StorageImageRead: return {shader, VK_ACCESS_2_SHADER_STORAGE_READ_BIT, VK_IMAGE_LAYOUT_GENERAL};
        case Use::StorageImageWrite: return {shader, VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT, VK_IMAGE_LAYOUT_GENERAL};
        case Use::StorageImageReadWrite:
            return {shader, VK_ACCESS_2_SHADER_STORAGE_READ_BIT | VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT,
                    VK_IMAGE_LAYOUT_GENERAL};
        case Use::ColorAttachmentWrite:
            return {VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT, VK_ACCESS_2_COLOR_ATTACHMENT_WRITE_BIT,
                    VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL};
        case Use::ColorAttachmentBlend:
            return {VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT,
                    VK_ACCESS_2_COLOR_ATTACHMENT_READ_BIT | VK_ACCESS_2_COLOR_ATTACHMENT_WRITE_BIT,
                    VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL};
        case Use::DepthStencilWrite:
            // The depth test reads before it writes.
            return {kFragmentTests,
                    VK_ACCESS_2_DEPTH_STENCIL_ATTACHMENT_READ_BIT | VK_ACCESS_2_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT,
                    VK_IMAGE_LAYOUT_DEPTH_STENCIL_ATTACHMENT_OPTIMAL};
        case Use::DepthStencilReadOnly:
            return {kFragmentTests, VK_ACCESS_2_DEPTH_STENCIL_ATTACHMENT_READ_BIT,
                    VK_IMAGE_LAYOUT_DEPTH_STENCIL_READ_ONLY_OPTIMAL};
        case Use::UniformBuffer: return {shader, VK_ACCESS_2_UNIFORM_READ_BIT};
        case Use::StorageBufferRead: return {shader, VK_ACCESS_2_SHADER_STORAGE_READ_BIT};
        case Use::StorageBufferWrite: return {shader, VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT};
        case Use::StorageBufferReadWrite:
            return {shader, VK_ACCESS_2_SHADER_STORAGE_READ_BIT | VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT};
        case Use::VertexBuffer:
            return {VK_PIPELINE_STAGE_2_VERTEX_ATTRIBUTE_INPUT_BIT, VK_ACCESS_2_VERTEX_ATTRIBUTE_READ_BIT};
        case Use::IndexBuffer: return {VK_PIPELINE_STAGE_2_INDEX_INPUT_BIT, VK_ACCESS_2_INDEX_READ_BIT};
        case Use::IndirectBuffer: return {VK_PIPELINE_STAGE_2_DRAW_INDIRECT_BIT, VK_ACCESS_2_INDIRECT_COMMAND_READ_BIT};
        case Use::TransferSrc:
            return {VK_PIPELINE_STAGE_2_COPY_BIT, VK_ACCESS_2_TRANSFER_READ_BIT, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL};
        case Use::TransferDst:
            return {VK_PIPELINE_STAGE_2_COPY_BIT, VK_ACCESS_2_TRANSFER_WRITE_BIT, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL};
        case Use::HostRead: return {VK_PIPELINE_STAGE_2_HOST_BIT, VK_ACCESS_2_HOST_READ_BIT};
    }
    throw InternalError("access_state: unknown use");
}

VkImageUsageFlags image_usage(Use use) {
    switch (use) {
        case Use::SampledRead: return VK_IMAGE_USAGE_SAMPLED_BIT;
        case Use::StorageImageRead:
        case Use::StorageImageWrite:
        case Use::StorageImageReadWrite: return VK_IMAGE_USAGE_STORAGE_BIT;
        case Use::ColorAttachmentWrite:
        case Use::ColorAttachmentBlend: return VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT;
        case Use::DepthStencilWrite:
        case Use::DepthStencilReadOnly: return VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT;
        case Use::TransferSrc: return VK_IMAGE_USAGE_TRANSFER_SRC_BIT;
        case Use::TransferDst: return VK_IMAGE_USAGE_TRANSFER_DST_BIT;
        default: return 0;
    }
}

VkBufferUsageFlags buffer_usage(Use use) {
    switch (use) {
        case Use::UniformBuffer: return VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT;
        case Use::StorageBufferRead:
        case Use::StorageBufferWrite:
        case Use::StorageBufferReadWrite: return VK_BUFFER_USAGE_STORAGE_BUFFER_BIT;
        case Use::VertexBuffer: return VK_BUFFER_USAGE_VERTEX_BUFFER_BIT;
        case Use::IndexBuffer: return VK_BUFFER_USAGE_INDEX_BUFFER_BIT;
        case Use::IndirectBuffer: return VK_BUFFER_USAGE_INDIRECT_BUFFER_BIT;
        case Use::TransferSrc: return VK_BUFFER_USAGE_TRANSFER_SRC_BIT;
        case Use::TransferDst: return VK_BUFFER_USAGE_TRANSFER_DST_BIT;
        default: return 0;
    }
}

namespace {

template <class Flags, size_t N>
std::string join_flag_names(Flags flags, const std::pair<Flags, const char*> (&table)[N]) {
    if (flags == 0) return "NONE";
    std::string text;
    for (const auto& [bit, name] : table) {
        if (flags & bit) {
            text += (text.empty() ? "" : "|") + std::string(name);
            flags &= ~bit;
        }
    }
    if (flags != 0) text += (text.empty() ? "" : "|") + std::string("0x") + std::to_string(flags);
    return text;
}

const std::pair<VkPipelineStageFlags2, const char*> kStageNames[] = {
    {VK_PIPELINE_STAGE_2_DRAW_INDIRECT_BIT, "DRAW_INDIRECT"},
    {VK_PIPELINE_STAGE_2_INDEX_INPUT_BIT, "INDEX_INPUT"},
    {VK_PIPELINE_STAGE_2_VERTEX_ATTRIBUTE_INPUT_BIT, "VERTEX_ATTRIBUTE_INPUT"},
    {VK_PIPELINE_STAGE_2_VERTEX_SHADER_BIT, "VERTEX_SHADER"},
    {VK_PIPELINE_STAGE_2_GEOMETRY_SHADER_BIT, "GEOMETRY_SHADER"},
    {VK_PIPELINE_STAGE_2_EARLY_FRAGMENT_TESTS_BIT, "EARLY_FRAGMENT_TESTS"},
    {VK_PIPELINE_STAGE_2_FRAGMENT_SHADER_BIT, "FRAGMENT_SHADER"},
    {VK_PIPELINE_STAGE_2_LATE_FRAGMENT_TESTS_BIT, "LATE_FRAGMENT_TESTS"},
    {VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT, "COLOR_ATTACHMENT_OUTPUT"},
    {VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT, "COMPUTE_SHADER"},
    {VK_PIPELINE_STAGE_2_COPY_BIT, "COPY"},
    {VK_PIPELINE_STAGE_2_BLIT_BIT, "BLIT"},
    {VK_PIPELINE_STAGE_2_CLEAR_BIT, "CLEAR"},
    {VK_PIPELINE_STAGE_2_HOST_BIT, "HOST"},
};

const std::pair<VkAccessFlags2, const char*> kAccessNames[] = {
    {VK_ACCESS_2_INDIRECT_COMMAND_READ_BIT, "INDIRECT_COMMAND_READ"},
    {VK_ACCESS_2_INDEX_READ_BIT, "INDEX_READ"},
    {VK_ACCESS_2_VERTEX_ATTRIBUTE_READ_BIT, "VERTEX_ATTRIBUTE_READ"},
    {VK_ACCESS_2_UNIFORM_READ_BIT, "UNIFORM_READ"},
    {VK_ACCESS_2_SHADER_SAMPLED_READ_BIT, "SHADER_SAMPLED_READ"},
    {VK_ACCESS_2_SHADER_STORAGE_READ_BIT, "SHADER_STORAGE_READ"},
    {VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT, "SHADER_STORAGE_WRITE"},
    {VK_ACCESS_2_COLOR_ATTACHMENT_READ_BIT, "COLOR_ATTACHMENT_READ"},
    {VK_ACCESS_2_COLOR_ATTACHMENT_WRITE_BIT, "COLOR_ATTACHMENT_WRITE"},
    {VK_ACCESS_2_DEPTH_STENCIL_ATTACHMENT_READ_BIT, "DEPTH_STENCIL_ATTACHMENT_READ"},
    {VK_ACCESS_2_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT, "DEPTH_STENCIL_ATTACHMENT_WRITE"},
    {VK_ACCESS_2_TRANSFER_READ_BIT, "TRANSFER_READ"},
    {VK_ACCESS_2_TRANSFER_WRITE_BIT, "TRANSFER_WRITE"},
    {VK_ACCESS_2_HOST_READ_BIT, "HOST_READ"},
    {VK_ACCESS_2_HOST_WRITE_BIT, "HOST_WRITE"},
};

}  // namespace

std::string stage_names(VkPipelineStageFlags2 stages) { return join_flag_names(stages, kStageNames); }

std::string access_names(VkAccessFlags2 access) { return join_flag_names(access, kAccessNames); }

const char* layout_name(VkImageLayout layout) {
    switch (layout) {
        case VK_IMAGE_LAYOUT_UNDEFINED: return "UNDEFINED";
        case VK_IMAGE_LAYOUT_GENERAL: return "GENERAL";
        case VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL: return "COLOR_ATTACHMENT_OPTIMAL";
        case VK_IMAGE_LAYOUT_DEPTH_STENCIL_ATTACHMENT_OPTIMAL: return "DEPTH_STENCIL_ATTACHMENT_OPTIMAL";
        case VK_IMAGE_LAYOUT_DEPTH_STENCIL_READ_ONLY_OPTIMAL: return "DEPTH_STENCIL_READ_ONLY_OPTIMAL";
        case VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL: return "SHADER_READ_ONLY_OPTIMAL";
        case VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL: return "TRANSFER_SRC_OPTIMAL";
        case VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL: return "TRANSFER_DST_OPTIMAL";
        case VK_IMAGE_LAYOUT_PRESENT_SRC_KHR: return "PRESENT_SRC";
        default: return "LAYOUT?";
    }
}

}  // namespace vkw::fg
