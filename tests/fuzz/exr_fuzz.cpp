// libFuzzer target: an EXR file (the input) through read_exr_bytes, what read_exr does once it has
// read the file: the header walk, OpenEXR's checker, then its reader. Every input must read or be
// refused with vkw::UserError. (The input is not written to a file: that took a fifth of the time.)
#include <cstddef>
#include <cstdint>

#include "engine/core/errors.hpp"
#include "engine/image/exr_io.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, std::size_t size) {
    try {
        vkw::read_exr_bytes({reinterpret_cast<const char*>(data), size}, "fuzz-input.exr");
    } catch (const vkw::UserError&) {}
    return 0;
}
