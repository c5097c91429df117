#include "tools/reference/scene_hash.hpp"

#include "engine/core/errors.hpp"
#include "engine/core/fnv1a.hpp"

#include <fstream>
#include <iterator>

namespace vkw::ref {

std::string scene_file_hash(const std::filesystem::path& file) {
    std::ifstream in(file, std::ios::binary);
    if (!in) throw UserError("cannot read '" + file.string() + "' to hash it");
    Fnv1a64 hash;
    for (std::istreambuf_iterator<char> it(in), end; it != end; ++it) hash.add_byte(static_cast<unsigned char>(*it));
    return hash.hex();
}

}  // namespace vkw::ref
