// libFuzzer target: an EXR file (the input) through read_exr, OpenEXR's checker first. Every
// input must read or be refused with vkw::UserError.
#include <cstddef>
#include <cstdint>

#include "engine/core/errors.hpp"
#include "engine/image/exr_io.hpp"
#include "tests/fuzz/file_fuzz.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, std::size_t size) {
    try {
        vkw::read_exr(vkw::fuzz::write_input(data, size, ".exr"));
    } catch (const vkw::UserError&) {}
    return 0;
}
