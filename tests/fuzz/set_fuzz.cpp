// libFuzzer target: one --set override (the input, as the command line passes it) applied to the
// built-in pool scene. Every input must apply or be refused with vkw::UserError.
#include <cstddef>
#include <cstdint>
#include <fstream>
#include <sstream>
#include <string>

#include "engine/core/errors.hpp"
#include "engine/scene/scene_loader.hpp"

namespace {

const std::string& pool_text() {
    static const std::string text = [] {
        std::ifstream file(VKWATER_SOURCE_DIR "/scenes/pool.json");
        std::stringstream bytes;
        bytes << file.rdbuf();
        return bytes.str();
    }();
    return text;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, std::size_t size) {
    const std::string override_text(reinterpret_cast<const char*>(data), size);
    // The shell cannot pass a NUL inside an argument.
    if (override_text.find('\0') != std::string::npos) return 0;
    try {
        vkw::parse_scene(pool_text(), VKWATER_SOURCE_DIR "/scenes/pool.json", {override_text});
    } catch (const vkw::UserError&) {}
    return 0;
}
