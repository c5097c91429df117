// Checks run on a file path before handing it to OpenEXR or stb, so that a wrong path
// becomes one readable UserError line instead of a library's generic failure.
#pragma once

#include <filesystem>
#include <string>

namespace vkw {

// The path in single quotes, the way every image I/O error message names a file.
std::string quoted_path(const std::filesystem::path& path);

// Throws UserError "cannot write '<path>': <why>" when the file could not be created or
// overwritten: empty path, path is a directory, parent directory missing or not a
// directory, or no permission.
void require_writable_file_path(const std::filesystem::path& path);

// Throws UserError "cannot read '<path>': <why>" when the path does not exist, is a
// directory, or cannot be opened for reading.
void require_readable_file_path(const std::filesystem::path& path);

}  // namespace vkw
