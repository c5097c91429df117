#include "engine/vk/shader_module.hpp"

#include "engine/core/errors.hpp"
#include "engine/vk/check.hpp"
#include "engine/vk/context.hpp"

#include <dlfcn.h>

#include <cstdlib>
#include <fstream>

namespace vkw {

std::filesystem::path shader_directory_among(const char* from_environment, const std::filesystem::path& module,
                                             const std::filesystem::path& build_tree) {
    if (from_environment && *from_environment) return from_environment;
    // Installed: <prefix>/share/vkwater/shaders beside <prefix>/bin/vkwater, <prefix>/lib/libvkwater.so
    // or <prefix>/lib/<multiarch>/libvkwater.so (Debian's library folder is one level deeper).
    const std::filesystem::path shaders = std::filesystem::path("share") / "vkwater" / "shaders";
    std::filesystem::path prefix = module.parent_path().parent_path();
    for (int level = 0; level < 2 && !module.empty(); ++level, prefix = prefix.parent_path()) {
        if (std::filesystem::is_directory(prefix / shaders)) return prefix / shaders;
    }
    if (!build_tree.empty() && std::filesystem::is_directory(build_tree)) return build_tree;
    return module.parent_path().parent_path() / shaders;  // named in the error when no shader is found
}

std::filesystem::path shader_directory() {
    // The file this code was loaded from: the shared library when a host links libvkwater.so,
    // the executable when the CLI or a test links the engine statically.
    Dl_info info{};
    std::filesystem::path module;
    if (dladdr(reinterpret_cast<const void*>(&shader_directory), &info) && info.dli_fname) {
        std::error_code ec;
        module = std::filesystem::canonical(info.dli_fname, ec);
    }
#ifdef VKWATER_DEFAULT_SHADER_DIR
    const std::filesystem::path build_tree = VKWATER_DEFAULT_SHADER_DIR;
#else
    const std::filesystem::path build_tree;
#endif
    return shader_directory_among(std::getenv("VKWATER_SHADER_DIR"), module, build_tree);
}

ShaderModule::ShaderModule(const Context& context, const std::string& name)
    : device_(context.device()), allocator_(context.allocator()), file_(name + ".spv") {
    const std::filesystem::path path = shader_directory() / (name + ".spv");
    std::ifstream file(path, std::ios::binary | std::ios::ate);
    if (!file) {
        throw InternalError(
            "shader '" + path.string() +
            "' not found (build the vkwater_shaders target, install vkwater, or set VKWATER_SHADER_DIR)");
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
