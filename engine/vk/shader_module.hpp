// Loads SPIR-V compiled at build time. Shaders are found in $VKWATER_SHADER_DIR, else where an
// install put them beside the binary holding this code (<prefix>/share/vkwater/shaders beside
// <prefix>/lib/libvkwater.so or <prefix>/bin/vkwater), else in the build tree's shaders/ folder
// (baked in at configure time). An installed copy thus never reads the build tree it came from.
#pragma once

#include <vulkan/vulkan.h>

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

namespace vkw {

class Context;

std::filesystem::path shader_directory();
// The rule itself: `from_environment` when set, else the installed folder beside `module` (the
// library or executable file) when it exists, else `build_tree` when it exists, else the
// installed folder (for the error message).
std::filesystem::path shader_directory_among(const char* from_environment, const std::filesystem::path& module,
                                             const std::filesystem::path& build_tree);

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
