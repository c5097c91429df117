// Path checks shared by the EXR and PNG writers and the EXR reader.
#include "engine/image/file_paths.hpp"

#include <unistd.h>  // access(): the only way to ask "may *this* process write here" (POSIX).

#include <fstream>
#include <system_error>

#include "engine/core/errors.hpp"

namespace vkw {

namespace fs = std::filesystem;

std::string quoted_path(const fs::path& path) {
    // Appending rather than `"'" + path.string() + "'"`: GCC 12 at -O3 reports a false
    // -Wrestrict on the latter (GCC bug 105329), which -Werror would turn into a failure.
    std::string quoted(1, '\'');
    quoted += path.string();
    quoted += '\'';
    return quoted;
}

void require_writable_file_path(const fs::path& path) {
    auto fail = [&](const std::string& why) { throw UserError("cannot write " + quoted_path(path) + ": " + why); };

    if (path.empty()) fail("the path is empty");

    // Error-code overloads throughout: a failed stat must become our message, not a
    // std::filesystem::filesystem_error.
    std::error_code ec;
    if (fs::is_directory(path, ec)) fail("it is a directory, not a file");

    const fs::path dir = path.has_parent_path() ? path.parent_path() : fs::path(".");
    const fs::file_status dir_status = fs::status(dir, ec);
    if (dir_status.type() == fs::file_type::not_found) {
        fail("directory " + quoted_path(dir) + " does not exist");
    }
    if (dir_status.type() == fs::file_type::none) {  // stat failed for another reason, e.g. EACCES
        fail("cannot access directory " + quoted_path(dir) + " (" + ec.message() + ")");
    }
    if (!fs::is_directory(dir_status)) fail(quoted_path(dir) + " is not a directory");

    if (fs::exists(path, ec)) {
        if (::access(path.c_str(), W_OK) != 0) fail("permission denied");
    } else if (::access(dir.c_str(), W_OK | X_OK) != 0) {
        fail("no permission to create files in directory " + quoted_path(dir));
    }
}

void require_readable_file_path(const fs::path& path) {
    auto fail = [&](const std::string& why) { throw UserError("cannot read " + quoted_path(path) + ": " + why); };

    if (path.empty()) fail("the path is empty");
    std::error_code ec;
    const fs::file_status status = fs::status(path, ec);
    if (status.type() == fs::file_type::not_found) fail("the file does not exist");
    if (status.type() == fs::file_type::none) fail(ec.message());
    if (fs::is_directory(status)) fail("it is a directory, not a file");
    // Opening it is the direct test of readability (permissions, ACLs, root all included).
    if (!std::ifstream(path, std::ios::binary).is_open()) fail("permission denied");
}

}  // namespace vkw
