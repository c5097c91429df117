// Pipelines with one push-descriptor set and a push-constant block: passes describe
// their bindings and fixed-function state, this file turns that into Vulkan objects.
#pragma once

#include <vulkan/vulkan.h>

#include <array>
#include <string>
#include <vector>

namespace vkw {

class Context;

// Left empty (no bindings, no push constants), the layout is the one the pipeline's shaders ask
// for (derive_pipeline_layout, engine/vk/spirv_reflection.hpp); a declared one is checked against
// them (check_pipeline_layout).
struct PipelineLayoutDesc {
    std::vector<VkDescriptorSetLayoutBinding> bindings;  // set 0, pushed at record time
    uint32_t push_constant_bytes = 0;                    // visible to every stage
    // Filled in by Pipeline: the shaders' name of each binding, in the order of `bindings` (empty
    // where no stage uses it). PassContext::bind finds a pass's resources by these names.
    std::vector<std::string> names;
};

struct GraphicsPipelineDesc {
    std::string vertex_shader;    // name under shaders/ without .spv
    std::string fragment_shader;  // empty: no fragment stage (depth/stencil-only passes)
    // The specialization constants of both stages: value i for constant_id i. Code a
    // constant turns off is compiled out (llvmpipe runs both sides of a branch that a push
    // constant decides, masked, so this is how a variant's unused paths cost nothing).
    std::vector<uint32_t> specialization_constants;
    PipelineLayoutDesc layout;
    std::vector<VkVertexInputBindingDescription> vertex_bindings;
    std::vector<VkVertexInputAttributeDescription> vertex_attributes;
    VkPrimitiveTopology topology = VK_PRIMITIVE_TOPOLOGY_TRIANGLE_LIST;
    VkCullModeFlags cull_mode = VK_CULL_MODE_NONE;
    bool depth_test = false;
    bool depth_write = false;
    VkCompareOp depth_compare = VK_COMPARE_OP_GREATER_OR_EQUAL;  // vkwater uses reversed-Z
    bool depth_clamp = false;
    VkStencilOpState stencil_front{};
    VkStencilOpState stencil_back{};
    bool stencil_test = false;
    bool additive_blend = false;
    std::vector<VkFormat> color_formats;
    VkFormat depth_format = VK_FORMAT_UNDEFINED;
    // Classic render-pass recording: the pipeline is made for this render pass
    // (subpass 0) instead of dynamic rendering.
    VkRenderPass render_pass = VK_NULL_HANDLE;
};

struct ComputePipelineDesc {
    std::string shader;
    PipelineLayoutDesc layout;
};

class Pipeline {
public:
    Pipeline(const Context& context, const GraphicsPipelineDesc& desc, const std::string& name);
    Pipeline(const Context& context, const ComputePipelineDesc& desc, const std::string& name);
    ~Pipeline();
    Pipeline(const Pipeline&) = delete;
    Pipeline& operator=(const Pipeline&) = delete;

    VkPipeline handle() const { return pipeline_; }
    VkPipelineLayout layout() const { return layout_; }
    VkPipelineBindPoint bind_point() const { return bind_point_; }
    // The layout the pipeline was made with: declared, or derived from its shaders.
    const PipelineLayoutDesc& layout_desc() const { return layout_desc_; }
    // A compute pipeline's workgroup size, read from its shader; 1 x 1 x 1 for graphics.
    const std::array<uint32_t, 3>& local_size() const { return local_size_; }

private:
    void create_layout(const Context& context, const PipelineLayoutDesc& desc, const std::string& name);
    VkDevice device_ = VK_NULL_HANDLE;
    // Context::allocator(), kept because objects must be freed with the callbacks that made them.
    const VkAllocationCallbacks* allocator_ = nullptr;
    VkDescriptorSetLayout set_layout_ = VK_NULL_HANDLE;
    VkPipelineLayout layout_ = VK_NULL_HANDLE;
    VkPipeline pipeline_ = VK_NULL_HANDLE;
    VkPipelineBindPoint bind_point_ = VK_PIPELINE_BIND_POINT_GRAPHICS;
    PipelineLayoutDesc layout_desc_;
    std::array<uint32_t, 3> local_size_{1, 1, 1};
};

}  // namespace vkw
