#include "tools/reference/scene_hash.hpp"

#include "engine/core/errors.hpp"

#include <cstdio>
#include <fstream>
#include <iterator>

namespace vkw::ref {

std::string scene_file_hash(const std::filesystem::path& file) {
    std::ifstream in(file, std::ios::binary);
    if (!in) throw UserError("cannot read '" + file.string() + "' to hash it");
    uint64_t hash = 14695981039346656037ull;  // FNV-1a offset basis
    for (std::istreambuf_iterator<char> it(in), end; it != end; ++it) {
        hash ^= static_cast<unsigned char>(*it);
        hash *= 1099511628211ull;  // FNV-1a prime
    }
    char text[17];
    std::snprintf(text, sizeof text, "%016llx", static_cast<unsigned long long>(hash));
    return text;
}

}  // namespace vkw::ref
