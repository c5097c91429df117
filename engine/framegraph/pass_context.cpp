#include "engine/framegraph/pass_context.hpp"

#include "engine/core/errors.hpp"
#include "engine/framegraph/executor.hpp"
#include "engine/vk/context.hpp"
#include "engine/vk/spirv_reflection.hpp"

#include <algorithm>

namespace vkw::fg {

const Context& PassContext::context() const { return executor_.context(); }

VkImage PassContext::image(ImageHandle handle) const { return executor_.image(handle.index); }
VkImageView PassContext::view(ImageHandle handle) const { return executor_.view(handle.index); }
VkBuffer PassContext::buffer(BufferHandle handle) const { return executor_.buffer(handle.index); }

VkExtent2D PassContext::extent(ImageHandle handle) const {
    return {executor_.graph().image_width(handle.index), executor_.graph().image_height(handle.index)};
}

VkDeviceSize PassContext::size(BufferHandle handle) const {
    return executor_.graph().resources()[handle.index].buffer.size;
}

VkExtent2D PassContext::render_extent() const {
    for (const ResourceUse& use : executor_.graph().passes()[pass_].uses) {
        if (use.use == Use::ColorAttachmentWrite || use.use == Use::ColorAttachmentBlend ||
            use.use == Use::DepthStencilWrite || use.use == Use::DepthStencilReadOnly) {
            return extent({use.resource, 0});
        }
    }
    return {0, 0};
}

const Pipeline& PassContext::pipeline(const std::string& key, GraphicsPipelineDesc desc) {
    const FrameGraph& graph = executor_.graph();
    const PassDecl& pass = graph.passes()[pass_];
    desc.color_formats.clear();
    desc.depth_format = VK_FORMAT_UNDEFINED;
    for (const ResourceUse& use : pass.uses) {
        const VkFormat format = graph.resources()[use.resource].image.format;
        if (use.use == Use::ColorAttachmentWrite || use.use == Use::ColorAttachmentBlend) {
            desc.color_formats.push_back(format);
        }
        if (use.use == Use::DepthStencilWrite || use.use == Use::DepthStencilReadOnly) desc.depth_format = format;
    }
    desc.render_pass = executor_.render_pass(pass_);
    // Pipelines made for a VkRenderPass and for dynamic rendering are different objects.
    const std::string full_key = pass.name + "/" + key + (desc.render_pass ? "/renderpass" : "/dynamic");
    return executor_.pipelines().get(executor_.context(), full_key, desc);
}

const Pipeline& PassContext::pipeline(const std::string& key, const ComputePipelineDesc& desc) {
    const std::string full_key = executor_.graph().passes()[pass_].name + "/" + key;
    return executor_.pipelines().get(executor_.context(), full_key, desc);
}

DescriptorBinding PassContext::sampled(uint32_t binding, ImageHandle handle) const {
    DescriptorBinding b{binding, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER};
    b.image = {executor_.linear_sampler(), view(handle), executor_.layout_in_pass(pass_, handle.index)};
    return b;
}

DescriptorBinding PassContext::sampled_nearest(uint32_t binding, ImageHandle handle) const {
    DescriptorBinding b = sampled(binding, handle);
    b.image.sampler = executor_.nearest_sampler();
    return b;
}

DescriptorBinding PassContext::storage_image(uint32_t binding, ImageHandle handle) const {
    DescriptorBinding b{binding, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE};
    b.image = {VK_NULL_HANDLE, view(handle), executor_.layout_in_pass(pass_, handle.index)};
    return b;
}

DescriptorBinding PassContext::storage_buffer(uint32_t binding, BufferHandle handle) const {
    DescriptorBinding b{binding, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER};
    b.buffer = {buffer(handle), 0, VK_WHOLE_SIZE};
    return b;
}

DescriptorBinding PassContext::uniform_buffer(uint32_t binding, BufferHandle handle) const {
    DescriptorBinding b{binding, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER};
    b.buffer = {buffer(handle), 0, VK_WHOLE_SIZE};
    return b;
}

void PassContext::bind(const Pipeline& pipeline, std::initializer_list<DescriptorBinding> bindings) const {
    bind(pipeline, std::vector<DescriptorBinding>(bindings));
}

void PassContext::bind(const Pipeline& pipeline, const std::vector<DescriptorBinding>& bindings) const {
    vkCmdBindPipeline(cmd_, pipeline.bind_point(), pipeline.handle());
    push_descriptors(pipeline, bindings);
}

void PassContext::push_descriptors(const Pipeline& pipeline, const std::vector<DescriptorBinding>& bindings) const {
    if (bindings.empty()) return;
    std::vector<VkWriteDescriptorSet> writes;
    const std::vector<VkDescriptorSetLayoutBinding>& layout = pipeline.layout_desc().bindings;
    for (const DescriptorBinding& binding : bindings) {
        // A binding the layout lacks is one this shader variant compiles out (the pass binds what
        // all its variants may read); a descriptor must have its binding's type (Vulkan's rule for
        // writes), else the pass and its shaders disagree.
        const auto slot = std::find_if(layout.begin(), layout.end(), [&](const VkDescriptorSetLayoutBinding& b) {
            return b.binding == binding.binding;
        });
        if (slot == layout.end()) continue;
        if (slot->descriptorType != binding.type) {
            throw InternalError("pass '" + executor_.graph().passes()[pass_].name + "' binds a " +
                                descriptor_type_name(binding.type) + " at binding " + std::to_string(binding.binding) +
                                ", where its pipeline's shaders read a " + descriptor_type_name(slot->descriptorType));
        }
        VkWriteDescriptorSet write{VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET};
        write.dstBinding = binding.binding;
        write.descriptorCount = 1;
        write.descriptorType = binding.type;
        const bool is_buffer =
            binding.type == VK_DESCRIPTOR_TYPE_STORAGE_BUFFER || binding.type == VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER;
        if (is_buffer) {
            write.pBufferInfo = &binding.buffer;
        } else {
            write.pImageInfo = &binding.image;
        }
        writes.push_back(write);
    }
    if (writes.empty()) return;
    executor_.context().push_descriptor_set()(cmd_, pipeline.bind_point(), pipeline.layout(), 0,
                                              static_cast<uint32_t>(writes.size()), writes.data());
}

void PassContext::push_constants(const Pipeline& pipeline, const void* data, uint32_t bytes) const {
    // The bytes are the pass's C++ mirror of the shaders' block: a different size means the two
    // have drifted apart (a member added on one side only).
    if (bytes != pipeline.layout_desc().push_constant_bytes) {
        throw InternalError("pass '" + executor_.graph().passes()[pass_].name + "' pushes " + std::to_string(bytes) +
                            " bytes of constants, but its pipeline's push-constant block is " +
                            std::to_string(pipeline.layout_desc().push_constant_bytes) + " bytes");
    }
    vkCmdPushConstants(cmd_, pipeline.layout(), VK_SHADER_STAGE_ALL, 0, bytes, data);
}

}  // namespace vkw::fg
