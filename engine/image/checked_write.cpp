// write_file_checked (checked_write.hpp), on POSIX file descriptors: std::ofstream cannot report
// fsync or close failures, and only the close reports some write errors (NFS, quotas).
#include "engine/image/checked_write.hpp"

#include "engine/core/errors.hpp"
#include "engine/image/file_paths.hpp"

#include <cerrno>
#include <cstring>
#include <string>
#include <vector>

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

namespace vkw {
namespace {

[[noreturn]] void fail(const std::filesystem::path& path, const std::string& why) {
    throw UserError("cannot write " + quoted_path(path) + ": " + why);
}

std::string errno_text() { return std::strerror(errno); }

// Writes all of `bytes` to fd, retrying short writes and EINTR; false with errno set on failure.
bool write_all(int fd, std::string_view bytes) {
    while (!bytes.empty()) {
        const ssize_t n = ::write(fd, bytes.data(), bytes.size());
        if (n < 0 && errno == EINTR) continue;
        if (n <= 0) {
            if (n == 0) errno = EIO;
            return false;
        }
        bytes.remove_prefix(static_cast<std::size_t>(n));
    }
    return true;
}

// A device, FIFO or other non-regular file, or what a /dev or /proc name such as /dev/stdout stands
// for: written where it is (truncated first when it is a regular file).
void write_in_place(const std::filesystem::path& path, std::string_view bytes, bool regular) {
    const int fd = ::open(path.c_str(), O_WRONLY | O_CLOEXEC | (regular ? O_TRUNC : 0));
    if (fd < 0) fail(path, errno_text());
    if (!write_all(fd, bytes)) {
        const std::string why = errno_text();
        ::close(fd);
        fail(path, why);
    }
    if (::close(fd) != 0) fail(path, errno_text());
}

// The mode a newly created file gets from the process's umask, or the replaced file's own.
mode_t file_mode(const std::filesystem::path& path) {
    struct stat existing {};
    if (::stat(path.c_str(), &existing) == 0) return existing.st_mode & 07777;
    const mode_t mask = ::umask(0);
    ::umask(mask);
    return 0666 & ~mask;
}

void write_by_rename(const std::filesystem::path& path, std::string_view bytes) {
    const std::filesystem::path folder = path.has_parent_path() ? path.parent_path() : std::filesystem::path(".");
    std::string pattern = (folder / ("." + path.filename().string() + ".partial-XXXXXX")).string();
    std::vector<char> name(pattern.begin(), pattern.end());
    name.push_back('\0');
    const int fd = ::mkstemp(name.data());
    if (fd < 0) fail(path, "cannot create a temporary file in " + quoted_path(folder) + ": " + errno_text());
    const std::string temporary(name.data());
    auto abandon = [&](const std::string& why) {
        ::close(fd);
        ::unlink(temporary.c_str());
        fail(path, why);
    };
    if (::fchmod(fd, file_mode(path)) != 0) abandon(errno_text());
    if (!write_all(fd, bytes)) abandon(errno_text());
    if (::fsync(fd) != 0) abandon(errno_text());
    if (::close(fd) != 0) {
        const std::string why = errno_text();
        ::unlink(temporary.c_str());
        fail(path, why);
    }
    if (::rename(temporary.c_str(), path.c_str()) != 0) {
        const std::string why = errno_text();
        ::unlink(temporary.c_str());
        fail(path, why);
    }
}

}  // namespace

void write_file_checked(const std::filesystem::path& path, std::string_view bytes) {
    namespace fs = std::filesystem;
    require_writable_file_path(path);
    std::error_code error;
    const fs::file_status status = fs::status(path, error);
    if (fs::exists(status) && !fs::is_regular_file(status)) {
        write_in_place(path, bytes, false);
        return;
    }
    // A symbolic link: the file it names is replaced, not the link; one into /dev or /proc
    // (/dev/stdout redirected to a file) is written in place, since the shell holds that file open.
    fs::path target = path;
    if (fs::is_symlink(fs::symlink_status(path, error))) {
        target = fs::canonical(path, error);
        if (error) fail(path, "cannot resolve the symbolic link (" + error.message() + ")");
        const std::string resolved = target.string();
        if (resolved.rfind("/proc/", 0) == 0 || resolved.rfind("/dev/", 0) == 0 ||
            path.string().rfind("/dev/", 0) == 0 || path.string().rfind("/proc/", 0) == 0) {
            write_in_place(path, bytes, true);
            return;
        }
    }
    write_by_rename(target, bytes);
}

}  // namespace vkw
