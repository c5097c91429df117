// A shader as a pass asks for it: its source under shaders/ and the macros its variant defines.
// The compiled file's name follows from the table that the build writes from the variants it
// compiles (shaders/CMakeLists.txt), so a pass never spells a variant's file name, and the build's
// list and the passes' requests cannot drift apart unnoticed: a request for a variant the build
// does not compile throws, naming the variants it does.
#pragma once

#include <set>
#include <string>
#include <vector>

namespace vkw {

struct ShaderVariant {
    std::string source;               // e.g. "receivers/receiver.frag"
    std::set<std::string> defines{};  // e.g. {"VKWATER_CAUSTICS", "VKWATER_SUN_SHADOW"}

    // Adds `macro` when `on`; returns *this, for chains such as
    // ShaderVariant{"sky/sky.frag"}.define("VKWATER_PER_PIXEL_MEDIUM", per_pixel).
    ShaderVariant& define(const std::string& macro, bool on = true);

    // The compiled file under shaders/ without ".spv", as pipeline descs take it, e.g.
    // "receivers/receiver.frag.per_pixel_caustics". Throws InternalError naming the source, the
    // macros asked for and the macro sets the build compiles it with.
    std::string file() const;
};

// Every compiled shader file, each with its source and macros, in the table's order (for tests).
struct CompiledShader {
    std::string source;
    std::set<std::string> defines;
    std::string file;
};
const std::vector<CompiledShader>& compiled_shaders();

}  // namespace vkw
