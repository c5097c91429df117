// What a pass's execute function sees at record time: the command buffer, the
// Vulkan objects behind its handles, descriptor bindings whose layouts come from the
// graph's declarations, and pipelines that are created on first use (so a culled
// pass never creates one).
#pragma once

#include "engine/framegraph/handles.hpp"
#include "engine/vk/pipeline.hpp"

#include <vulkan/vulkan.h>

#include <initializer_list>
#include <map>
#include <memory>
#include <string>
#include <vector>

namespace vkw {
class Context;
}

namespace vkw::fg {

class FrameExecutor;

// Pipelines outlive frame-graph recompiles; the key is the pass name plus the
// pass's own key, and the recording kind.
class PipelineStore {
public:
    template <class Desc>
    const Pipeline& get(const Context& context, const std::string& key, const Desc& desc) {
        auto& slot = pipelines_[key];
        if (!slot) slot = std::make_unique<Pipeline>(context, desc, key);
        return *slot;
    }
    size_t size() const { return pipelines_.size(); }
    bool contains(const std::string& key) const { return pipelines_.count(key) > 0; }

private:
    std::map<std::string, std::unique_ptr<Pipeline>> pipelines_;
};

struct DescriptorBinding {
    uint32_t binding = 0;
    VkDescriptorType type = VK_DESCRIPTOR_TYPE_MAX_ENUM;
    VkDescriptorImageInfo image{};
    VkDescriptorBufferInfo buffer{};
};

class PassContext {
public:
    PassContext(FrameExecutor& executor, VkCommandBuffer cmd, uint32_t pass)
        : executor_(executor), cmd_(cmd), pass_(pass) {}

    VkCommandBuffer cmd() const { return cmd_; }
    const Context& context() const;

    VkImage image(ImageHandle handle) const;
    VkImageView view(ImageHandle handle) const;
    VkExtent2D extent(ImageHandle handle) const;
    VkBuffer buffer(BufferHandle handle) const;
    VkDeviceSize size(BufferHandle handle) const;
    // Size of a graphics pass's attachments (its render area).
    VkExtent2D render_extent() const;

    // Pipelines, made once per key. Graphics descs get this pass's attachment formats
    // and, in render-pass recording, its VkRenderPass.
    const Pipeline& pipeline(const std::string& key, GraphicsPipelineDesc desc);
    const Pipeline& pipeline(const std::string& key, const ComputePipelineDesc& desc);

    // Descriptors for handles this pass declared; the image layouts are the graph's.
    DescriptorBinding sampled(uint32_t binding, ImageHandle handle) const;
    // The same with a nearest-filter sampler: for formats without linear filtering (depth).
    DescriptorBinding sampled_nearest(uint32_t binding, ImageHandle handle) const;
    DescriptorBinding storage_image(uint32_t binding, ImageHandle handle) const;
    DescriptorBinding storage_buffer(uint32_t binding, BufferHandle handle) const;
    DescriptorBinding uniform_buffer(uint32_t binding, BufferHandle handle) const;

    // Binds the pipeline and pushes its descriptor set 0.
    void bind(const Pipeline& pipeline, std::initializer_list<DescriptorBinding> bindings) const;
    void bind(const Pipeline& pipeline, const std::vector<DescriptorBinding>& bindings) const;
    // Pushes these bindings of the bound pipeline's set 0 again; the others keep their values
    // (push descriptors update incrementally): per-draw resources such as a mesh's texture.
    void push_descriptors(const Pipeline& pipeline, const std::vector<DescriptorBinding>& bindings) const;
    void push_constants(const Pipeline& pipeline, const void* data, uint32_t bytes) const;
    template <class T>
    void push_constants(const Pipeline& pipeline, const T& data) const {
        push_constants(pipeline, &data, sizeof(T));
    }

private:
    FrameExecutor& executor_;
    VkCommandBuffer cmd_;
    uint32_t pass_;
};

}  // namespace vkw::fg
