#include "engine/vk/shader_variant.hpp"

#include "engine/core/errors.hpp"

#include <sstream>

namespace vkw {
namespace {

struct TableEntry {
    const char* source;
    const char* macros;  // sorted, ','-joined
    const char* file;
};

// Written at configure time by vkwater_write_shader_variant_table (cmake/CompileShaders.cmake).
constexpr TableEntry kTable[] = {
#include <shader_variants/variant_table.inc>
};

std::set<std::string> split_macros(const std::string& text) {
    std::set<std::string> macros;
    std::stringstream stream(text);
    for (std::string macro; std::getline(stream, macro, ',');) {
        if (!macro.empty()) macros.insert(macro);
    }
    return macros;
}

std::string macro_list(const std::set<std::string>& macros) {
    if (macros.empty()) return "none";
    std::string text;
    for (const std::string& macro : macros) text += (text.empty() ? "" : ", ") + macro;
    return text;
}

}  // namespace

ShaderVariant& ShaderVariant::define(const std::string& macro, bool on) {
    if (on) defines.insert(macro);
    return *this;
}

const std::vector<CompiledShader>& compiled_shaders() {
    static const std::vector<CompiledShader> shaders = [] {
        std::vector<CompiledShader> all;
        for (const TableEntry& entry : kTable) all.push_back({entry.source, split_macros(entry.macros), entry.file});
        return all;
    }();
    return shaders;
}

std::string ShaderVariant::file() const {
    std::string built;
    for (const CompiledShader& shader : compiled_shaders()) {
        if (shader.source != source) continue;
        if (shader.defines == defines) return shader.file;
        built += "\n  " + macro_list(shader.defines);
    }
    if (built.empty()) throw InternalError("shader '" + source + "' is not compiled by shaders/CMakeLists.txt");
    throw InternalError("shader '" + source + "' is not compiled with the macros " + macro_list(defines) +
                        " (shaders/CMakeLists.txt); its variants define:" + built);
}

}  // namespace vkw
