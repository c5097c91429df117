#include "engine/scene/file_scope.hpp"

#include <system_error>

#include "engine/core/errors.hpp"
#include "engine/core/message_text.hpp"

namespace vkw {
namespace {

// The path with every symbolic link and ".." resolved as far as the path exists: a link inside
// the tree that points outside it is outside.
std::filesystem::path real_path(const std::filesystem::path& path) {
    std::error_code error;
    std::filesystem::path real = std::filesystem::weakly_canonical(std::filesystem::absolute(path, error), error);
    return error ? std::filesystem::absolute(path).lexically_normal() : real;
}

bool is_inside(const std::filesystem::path& path, const std::filesystem::path& folder) {
    const std::filesystem::path relative = path.lexically_relative(folder);
    return !relative.empty() && *relative.begin() != "..";
}

int hex_digit(char c) {
    if (c >= '0' && c <= '9') return c - '0';
    if (c >= 'a' && c <= 'f') return c - 'a' + 10;
    if (c >= 'A' && c <= 'F') return c - 'A' + 10;
    return -1;
}

}  // namespace

FileScope::FileScope(const std::filesystem::path& scene_file, bool allow_outside)
    : scene_folder_(scene_file.parent_path()), allow_outside_(allow_outside) {}

std::filesystem::path FileScope::resolve(const std::filesystem::path& from_folder, const std::string& name,
                                         const std::string& what, const std::string& written_as) const {
    const std::filesystem::path path = from_folder / name;
    if (allow_outside_) return path;
    const std::filesystem::path root = real_path(scene_folder_.empty() ? "." : scene_folder_);
    if (!is_inside(real_path(path), root)) {
        throw UserError(what + " '" + shortened_input(one_line(written_as.empty() ? name : written_as), 80) +
                        "' resolves outside the scene's folder '" + root.string() +
                        "' (accepted: a path inside it, or --allow-outside-paths)");
    }
    return path;
}

std::string decode_uri_escapes(const std::string& uri) {
    std::string decoded;
    decoded.reserve(uri.size());
    for (std::size_t i = 0; i < uri.size(); ++i) {
        if (uri[i] == '%' && i + 2 < uri.size() && hex_digit(uri[i + 1]) >= 0 && hex_digit(uri[i + 2]) >= 0) {
            decoded += char(hex_digit(uri[i + 1]) * 16 + hex_digit(uri[i + 2]));
            i += 2;
        } else {
            decoded += uri[i];
        }
    }
    return decoded;
}

}  // namespace vkw
