// What a SPIR-V module asks of its pipeline layout (descriptor bindings and the push-constant
// block), read from the module itself, and the check that a pipeline's declared layout provides
// it. A pass's C++ layout and its GLSL are written apart; without the check a mismatch shows up
// only as a validation message when validation is on, and as undefined behaviour when it is not.
#pragma once

#include "engine/vk/pipeline.hpp"

#include <vulkan/vulkan.h>

#include <cstdint>
#include <string>
#include <vector>

namespace vkw {

struct ReflectedBinding {
    uint32_t set = 0;
    uint32_t binding = 0;
    VkDescriptorType type = VK_DESCRIPTOR_TYPE_MAX_ENUM;
    uint32_t count = 1;  // descriptors in the binding (arrays of arrays: the product); 1 for runtime arrays
    // The shaders' name for it: a block's type name (`Flux` in `buffer Flux { ... };`), else the
    // variable's (`source` in `uniform sampler2D source;`). Passes bind their resources by it.
    std::string name;
};

struct ReflectedStage {
    std::string shader;  // the file, e.g. "sky/sky.frag.frame.spv" (for messages)
    VkShaderStageFlagBits stage = VK_SHADER_STAGE_ALL;
    std::vector<ReflectedBinding> bindings;  // those the entry point uses, sorted by (set, binding)
    uint32_t push_constant_bytes = 0;        // the push-constant block's declared size (read or not); 0: none
    uint32_t local_size[3] = {1, 1, 1};      // a compute stage's workgroup size (literal sizes)
};

// Reflects a SPIR-V module with one entry point. `shader` only names it in the result and in
// errors. Throws InternalError when the module cannot be parsed.
ReflectedStage reflect_spirv(const std::vector<uint32_t>& words, const std::string& shader);

// "storage buffer", "combined image sampler", ...
std::string descriptor_type_name(VkDescriptorType type);

// Throws InternalError naming the pass, the shader and the binding when `declared` does not provide
// what a stage uses (the rules are in the .cpp). Returns the declared bindings that no stage uses.
std::vector<VkDescriptorSetLayoutBinding> check_pipeline_layout(const std::string& pass,
                                                                const PipelineLayoutDesc& declared,
                                                                const std::vector<ReflectedStage>& stages);

// The layout the stages ask for (a pipeline whose desc leaves its layout empty gets this one):
// set 0's bindings as the shaders declare them, each visible to the stages that use it, and the
// longest push-constant block. The descriptor types of a binding the stages share must agree; a
// binding in another set than 0 is refused. Throws InternalError naming the pass and the shader.
// Recorded like a checked layout (layout_check_records), with no unused binding.
PipelineLayoutDesc derive_pipeline_layout(const std::string& pass, const std::vector<ReflectedStage>& stages);

// The shaders' name of each of `layout`'s bindings, in its order (PipelineLayoutDesc::names): empty
// for a binding no stage uses. Throws InternalError naming the pass when two stages name one
// binding differently or two bindings share a name (a pass could not tell them apart).
std::vector<std::string> name_layout_bindings(const std::string& pass, const PipelineLayoutDesc& layout,
                                              const std::vector<ReflectedStage>& stages);

// Every pipeline checked in this process, for the figures of a test: pipelines checked, and the
// declared bindings that none of a pipeline's stages uses.
struct LayoutCheckRecord {
    std::string pass;
    std::vector<std::string> shaders;
    std::vector<VkDescriptorSetLayoutBinding> unused;
    uint32_t declared_push_bytes = 0;
    std::vector<uint32_t> shader_push_bytes;  // per stage, in the order of `shaders`
};
std::vector<LayoutCheckRecord> layout_check_records();

}  // namespace vkw
