// What a pass's execute function sees at record time: the command buffer, the
// Vulkan objects behind its handles, descriptor bindings whose layouts come from the
// graph's declarations, and pipelines that are created on first use (so a culled
// pass never creates one).
#pragma once

#include "engine/framegraph/frame_graph.hpp"
#include "engine/framegraph/handles.hpp"
#include "engine/vk/pipeline.hpp"

#include <vulkan/vulkan.h>

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

// One descriptor of a pipeline's set 0, for the binding its shaders call `name`.
struct DescriptorBinding {
    std::string name;
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

    // Binds the pipeline and pushes its descriptor set 0: every binding its shaders use gets the
    // resource this pass declared under the binding's name (PassBuilder's named uses), or the one
    // of `extra` so named (resources outside the graph, a part of a buffer). A binding the shaders
    // use that neither provides throws InternalError naming it: the pass and its shaders disagree.
    void bind(const Pipeline& pipeline, const std::vector<DescriptorBinding>& extra = {}) const;
    // Pushes these bindings of the bound pipeline's set 0 again; the others keep their values
    // (push descriptors update incrementally): per-draw resources such as a mesh's texture.
    // A name the pipeline's shaders do not use is skipped: the variant drawn compiles it out.
    void push_descriptors(const Pipeline& pipeline, const std::vector<DescriptorBinding>& bindings) const;

    // Descriptors for `extra` and push_descriptors: `handle` (declared by this pass, in the
    // graph's layout) for the binding `name`.
    DescriptorBinding sampled(std::string name, ImageHandle handle, Filter filter = Filter::Linear) const;
    DescriptorBinding storage_image(std::string name, ImageHandle handle) const;
    // `range` bytes from `offset` (the whole buffer by default).
    DescriptorBinding storage_buffer(std::string name, BufferHandle handle, VkDeviceSize offset = 0,
                                     VkDeviceSize range = VK_WHOLE_SIZE) const;
    DescriptorBinding uniform_buffer(std::string name, BufferHandle handle) const;

    void push_constants(const Pipeline& pipeline, const void* data, uint32_t bytes) const;
    // Records enough workgroups of the compute pipeline's size (its shader's local_size) to cover
    // width x height x depth invocations; the shader returns early past the end.
    void dispatch(const Pipeline& pipeline, uint32_t width, uint32_t height = 1, uint32_t depth = 1) const;
    // ... to cover one invocation per texel of `image`.
    void dispatch(const Pipeline& pipeline, ImageHandle image) const;
    template <class T>
    void push_constants(const Pipeline& pipeline, const T& data) const {
        push_constants(pipeline, &data, sizeof(T));
    }

private:
    // The descriptor of one of this pass's named uses.
    DescriptorBinding declared(const ResourceUse& use) const;
    [[noreturn]] void fail(const std::string& what) const;

    FrameExecutor& executor_;
    VkCommandBuffer cmd_;
    uint32_t pass_;
};

}  // namespace vkw::fg
