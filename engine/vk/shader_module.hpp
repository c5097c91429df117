// Loads SPIR-V compiled at build time. Shaders are found in $VKWATER_SHADER_DIR, else
// in the build tree's shaders/ folder (baked in at configure time), else next to the
// executable in ../share/vkwater/shaders.
#pragma once

#include <vulkan/vulkan.h>

#include <filesystem>
#include <string>

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

private:
    VkDevice device_ = VK_NULL_HANDLE;
    VkShaderModule module_ = VK_NULL_HANDLE;
};

}  // namespace vkw
