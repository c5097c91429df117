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

void PassContext::fail(const std::string& what) const {
    throw InternalError("pass '" + executor_.graph().passes()[pass_].name + "' " + what);
}

DescriptorBinding PassContext::sampled(std::string name, ImageHandle handle, Filter filter) const {
    DescriptorBinding b{std::move(name), VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER};
    const VkSampler sampler = filter == Filter::Nearest ? executor_.nearest_sampler() : executor_.linear_sampler();
    b.image = {sampler, view(handle), executor_.layout_in_pass(pass_, handle.index)};
    return b;
}

DescriptorBinding PassContext::storage_image(std::string name, ImageHandle handle) const {
    DescriptorBinding b{std::move(name), VK_DESCRIPTOR_TYPE_STORAGE_IMAGE};
    b.image = {VK_NULL_HANDLE, view(handle), executor_.layout_in_pass(pass_, handle.index)};
    return b;
}

DescriptorBinding PassContext::storage_buffer(std::string name, BufferHandle handle, VkDeviceSize offset,
                                              VkDeviceSize range) const {
    DescriptorBinding b{std::move(name), VK_DESCRIPTOR_TYPE_STORAGE_BUFFER};
    b.buffer = {buffer(handle), offset, range};
    return b;
}

DescriptorBinding PassContext::uniform_buffer(std::string name, BufferHandle handle) const {
    DescriptorBinding b{std::move(name), VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER};
    b.buffer = {buffer(handle), 0, VK_WHOLE_SIZE};
    return b;
}

DescriptorBinding PassContext::declared(const ResourceUse& use) const {
    const ImageHandle image{use.resource, use.version_read};
    const BufferHandle buffer_handle{use.resource, use.version_read};
    switch (use.use) {
        case Use::SampledRead: return sampled(use.binding, image, use.filter);
        case Use::StorageImageRead:
        case Use::StorageImageWrite:
        case Use::StorageImageReadWrite: return storage_image(use.binding, image);
        case Use::UniformBuffer: return uniform_buffer(use.binding, buffer_handle);
        case Use::StorageBufferRead:
        case Use::StorageBufferWrite:
        case Use::StorageBufferReadWrite: return storage_buffer(use.binding, buffer_handle);
        default: fail("binds its " + std::string(use_name(use.use)) + " use to '" + use.binding + "'");
    }
}

void PassContext::bind(const Pipeline& pipeline, const std::vector<DescriptorBinding>& extra) const {
    vkCmdBindPipeline(cmd_, pipeline.bind_point(), pipeline.handle());
    const PipelineLayoutDesc& layout = pipeline.layout_desc();
    const std::vector<ResourceUse>& uses = executor_.graph().passes()[pass_].uses;
    std::vector<DescriptorBinding> bindings = extra;
    for (size_t i = 0; i < layout.names.size(); ++i) {
        const std::string& name = layout.names[i];
        if (name.empty()) continue;  // a declared layout's binding that no stage uses
        if (std::any_of(extra.begin(), extra.end(), [&](const DescriptorBinding& b) { return b.name == name; })) {
            continue;
        }
        const auto use =
            std::find_if(uses.begin(), uses.end(), [&](const ResourceUse& u) { return u.binding == name; });
        if (use == uses.end()) {
            fail("declares no resource for '" + name + "' (binding " + std::to_string(layout.bindings[i].binding) +
                 ", a " + descriptor_type_name(layout.bindings[i].descriptorType) + "), which its shaders read");
        }
        bindings.push_back(declared(*use));
    }
    push_descriptors(pipeline, bindings);
}

void PassContext::push_descriptors(const Pipeline& pipeline, const std::vector<DescriptorBinding>& bindings) const {
    if (bindings.empty()) return;
    std::vector<VkWriteDescriptorSet> writes;
    const PipelineLayoutDesc& layout = pipeline.layout_desc();
    for (const DescriptorBinding& binding : bindings) {
        // A name the shaders do not use is one this variant compiles out (the pass declares what
        // all its variants may read); a descriptor must have its binding's type (Vulkan's rule for
        // writes), else the pass and its shaders disagree.
        const auto slot = std::find(layout.names.begin(), layout.names.end(), binding.name);
        if (binding.name.empty() || slot == layout.names.end()) continue;
        const VkDescriptorSetLayoutBinding& target = layout.bindings[size_t(slot - layout.names.begin())];
        if (target.descriptorType != binding.type) {
            fail("binds a " + descriptor_type_name(binding.type) + " to '" + binding.name + "' (binding " +
                 std::to_string(target.binding) + "), where its pipeline's shaders read a " +
                 descriptor_type_name(target.descriptorType));
        }
        VkWriteDescriptorSet write{VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET};
        write.dstBinding = target.binding;
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

void PassContext::dispatch(const Pipeline& pipeline, uint32_t width, uint32_t height, uint32_t depth) const {
    const std::array<uint32_t, 3>& group = pipeline.local_size();
    const auto groups = [](uint32_t invocations, uint32_t side) { return (invocations + side - 1) / side; };
    vkCmdDispatch(cmd_, groups(width, group[0]), groups(height, group[1]), groups(depth, group[2]));
}

void PassContext::dispatch(const Pipeline& pipeline, ImageHandle image) const {
    const VkExtent2D size = extent(image);
    dispatch(pipeline, size.width, size.height);
}

}  // namespace vkw::fg
