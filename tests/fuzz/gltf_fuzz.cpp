// libFuzzer target: a .gltf or .glb file (the input) through the pre-scan, tinygltf and the
// mesh loader. Every input must load or be refused with vkw::UserError.
#include <cstddef>
#include <cstdint>

#include "engine/core/errors.hpp"
#include "engine/scene/gltf_mesh.hpp"
#include "tests/fuzz/file_fuzz.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, std::size_t size) {
    const bool binary = size >= 4 && data[0] == 'g' && data[1] == 'l' && data[2] == 'T' && data[3] == 'F';
    try {
        vkw::load_gltf_mesh(vkw::fuzz::write_input(data, size, binary ? ".glb" : ".gltf"));
    } catch (const vkw::UserError&) {}
    return 0;
}
