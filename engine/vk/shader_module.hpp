// Loads SPIR-V compiled at build time. Shaders are found in $VKWATER_SHADER_DIR, else
// in the build tree's shaders/ folder (baked in at configure time), else next to the
// executable in ../share/vkwater/shaders.
#pragma once

#include <vulkan/vulkan.h>

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

namespace vkw {

class Context;

std::filesystem::path shader_directory();

class ShaderModule {
public:
    // name: path under shaders/ without ".spv", e.g. "sky/sky.frag".
    ShaderModule(const Context& context, const std::string& name);
    ~ShaderModule();
    ShaderModule(const ShaderModule&) = delete;
    ShaderModule& operator=(const ShaderModule&) = delete;
    VkShaderModule handle() const { return module_; }
    // The SPIR-V as loaded, kept for reflection (engine/vk/spirv_reflection.hpp) without a second read.
    const std::vector<uint32_t>& words() const { return words_; }
    // The file under shaders/, e.g. "sky/sky.frag.frame.spv".
    const std::string& file() const { return file_; }

private:
    VkDevice device_ = VK_NULL_HANDLE;
    // Context::allocator(), kept because objects must be freed with the callbacks that made them.
    const VkAllocationCallbacks* allocator_ = nullptr;
    VkShaderModule module_ = VK_NULL_HANDLE;
    std::vector<uint32_t> words_;
    std::string file_;
};

}  // namespace vkw
