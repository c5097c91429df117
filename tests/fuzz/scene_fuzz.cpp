// libFuzzer target: scene JSON text through the whole loader (parse, validate). Every input must
// load or be refused with vkw::UserError; any other exception, a crash or a sanitizer report is
// a bug. Scenes whose receivers name glTF files resolve them in the current folder's tree.
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "engine/core/errors.hpp"
#include "engine/scene/scene_loader.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, std::size_t size) {
    try {
        vkw::parse_scene(std::string_view(reinterpret_cast<const char*>(data), size), "fuzz.json");
    } catch (const vkw::UserError&) {}
    return 0;
}
