// For the loaders that read a path (glTF, EXR): each input written to one scratch file, named
// with this process's id so that parallel fuzzers do not share it.
#pragma once

#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <string>

namespace vkw::fuzz {

inline std::filesystem::path write_input(const uint8_t* data, std::size_t size, const std::string& extension) {
    static const std::filesystem::path file =
        std::filesystem::temp_directory_path() / ("vkwater_fuzz_" + std::to_string(::getpid()) + extension);
    std::ofstream(file, std::ios::binary | std::ios::trunc)
        .write(reinterpret_cast<const char*>(data), std::streamsize(size));
    return file;
}

}  // namespace vkw::fuzz
