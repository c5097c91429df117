#include "engine/vk/shader_module.hpp"

#include "engine/core/errors.hpp"
#include "engine/vk/check.hpp"
#include "engine/vk/context.hpp"

#include <cstdlib>
#include <fstream>

namespace vkw {

std::filesystem::path shader_directory() {
    if (const char* dir = std::getenv("VKWATER_SHADER_DIR"); dir && *dir) return dir;
#ifdef VKWATER_DEFAULT_SHADER_DIR
    if (std::filesystem::is_directory(VKWATER_DEFAULT_SHADER_DIR)) return VKWATER_DEFAULT_SHADER_DIR;
#endif
    std::error_code ec;
    const std::filesystem::path exe = std::filesystem::read_symlink("/proc/self/exe", ec);
    return exe.parent_path().parent_path() / "share" / "vkwater" / "shaders";
}

ShaderModule::ShaderModule(const Context& context, const std::string& name)
    : device_(context.device()), allocator_(context.allocator()), file_(name + ".spv") {
    const std::filesystem::path path = shader_directory() / (name + ".spv");
    std::ifstream file(path, std::ios::binary | std::ios::ate);
    if (!file) {
        throw InternalError("shader '" + path.string() +
                            "' not found (build the vkwater_shaders target, or set VKWATER_SHADER_DIR)");
    }
    const std::streamsize size = file.tellg();
    if (size <= 0 || size % 4 != 0) throw InternalError("shader '" + path.string() + "' is not SPIR-V");
    words_.resize(static_cast<size_t>(size) / 4);
    file.seekg(0);
    file.read(reinterpret_cast<char*>(words_.data()), size);

    VkShaderModuleCreateInfo info{VK_STRUCTURE_TYPE_SHADER_MODULE_CREATE_INFO};
    info.codeSize = static_cast<size_t>(size);
    info.pCode = words_.data();
    VKW_CHECK(vkCreateShaderModule(device_, &info, allocator_, &module_), "shader '" + name + "'");
    context.set_name(module_, VK_OBJECT_TYPE_SHADER_MODULE, name);
}

ShaderModule::~ShaderModule() {
    if (module_) vkDestroyShaderModule(device_, module_, allocator_);
}

}  // namespace vkw
