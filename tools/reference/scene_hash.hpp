// The fingerprint of a scene file recorded in tests/references/manifest.json: a
// reference is valid only for the exact bytes of the scene it was rendered from.
// FNV-1a, 64 bits, over the file's bytes, printed as 16 hex digits.
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>

namespace vkw::ref {

std::string scene_file_hash(const std::filesystem::path& file);

}  // namespace vkw::ref
