// Tests that both writers turn a bad output path into a one-line UserError naming the path,
// before any library gets to see it.
#include <gtest/gtest.h>

#include <sys/wait.h>
#include <unistd.h>

#include <filesystem>
#include <functional>
#include <string>
#include <vector>

#include "engine/core/errors.hpp"
#include "engine/image/exr_io.hpp"
#include "engine/image/file_paths.hpp"
#include "engine/image/png_preview.hpp"
#include "tests/image/image_test_support.hpp"

namespace vkw {
namespace {

namespace fs = std::filesystem;
using test::expect_user_error;
using test::ScratchDir;

struct NamedWriter {
    std::string name;
    std::function<void(const fs::path&)> write;
};

// Every public writer of the module: each must reject the same bad paths the same way.
std::vector<NamedWriter> all_writers() {
    const ImageRGBA32F image = test::make_test_image(2, 2);
    return {
        {"write_exr float", [image](const fs::path& p) { write_exr(p, image); }},
        {"write_exr half", [image](const fs::path& p) { write_exr(p, image, ExrPixelType::Half); }},
        {"write_png_preview", [image](const fs::path& p) { write_png_preview(p, image, 1.0f); }},
    };
}

// Root may write anywhere, and CI runs as root: permission checks run in a forked child
// that drops to the unprivileged user 'nobody' first, so they are enforced (and tested)
// whoever runs the suite. Returns what `check` returned in the child.
bool run_unprivileged(const std::function<bool()>& check) {
    const pid_t child = ::fork();
    if (child == 0) {
        if (::geteuid() == 0 && (::setgid(65534) != 0 || ::setuid(65534) != 0)) ::_exit(2);
        bool ok = false;
        try {
            ok = check();
        } catch (...) {}
        ::_exit(ok ? 0 : 1);
    }
    int status = 0;
    ::waitpid(child, &status, 0);
    return WIFEXITED(status) && WEXITSTATUS(status) == 0;
}

// True when writing `path` with every writer throws a UserError whose message names the
// path and contains `what`.
bool every_writer_refuses(const fs::path& path, const std::string& what) {
    for (const NamedWriter& writer : all_writers()) {
        try {
            writer.write(path);
            return false;
        } catch (const UserError& error) {
            const std::string message = error.what();
            if (message.find(path.string()) == std::string::npos || message.find(what) == std::string::npos) {
                return false;
            }
        }
    }
    return true;
}

TEST(image_file_paths, MissingDirectoryIsUserError) {
    ScratchDir dir;
    const fs::path missing = dir / "missing";
    for (const NamedWriter& writer : all_writers()) {
        SCOPED_TRACE(writer.name);
        const fs::path path = missing / "x.out";
        expect_user_error([&] { writer.write(path); }, path, "directory '" + missing.string() + "' does not exist");
        EXPECT_FALSE(fs::exists(missing));
    }
}

TEST(image_file_paths, DirectoryAsPathIsUserError) {
    ScratchDir dir;
    for (const NamedWriter& writer : all_writers()) {
        SCOPED_TRACE(writer.name);
        expect_user_error([&] { writer.write(dir.path()); }, dir.path(), "is a directory");
    }
}

TEST(image_file_paths, FileAsParentDirectoryIsUserError) {
    ScratchDir dir;
    test::write_text(dir / "plain", "x");
    for (const NamedWriter& writer : all_writers()) {
        SCOPED_TRACE(writer.name);
        const fs::path path = dir / "plain" / "x.out";
        expect_user_error([&] { writer.write(path); }, path, "is not a directory");
    }
}

TEST(image_file_paths, EmptyPathIsUserError) {
    for (const NamedWriter& writer : all_writers()) {
        SCOPED_TRACE(writer.name);
        expect_user_error([&] { writer.write(fs::path()); }, fs::path(), "the path is empty");
    }
}

TEST(image_file_paths, ReadOnlyDirectoryIsUserError) {
    ScratchDir dir;
    const fs::path locked = dir / "locked";
    fs::create_directory(locked);
    fs::permissions(locked,
                    fs::perms::owner_read | fs::perms::owner_exec | fs::perms::others_read | fs::perms::others_exec);
    EXPECT_TRUE(run_unprivileged([&] { return every_writer_refuses(locked / "x.out", "no permission"); }));
    fs::permissions(locked, fs::perms::owner_all);  // so ScratchDir can remove it
}

TEST(image_file_paths, ReadOnlyFileIsUserError) {
    ScratchDir dir;
    const fs::path path = dir / "readonly.out";
    test::write_text(path, "x");
    fs::permissions(path, fs::perms::owner_read | fs::perms::others_read);
    EXPECT_TRUE(run_unprivileged([&] { return every_writer_refuses(path, "permission denied"); }));
}

TEST(image_file_paths, BareFileNameChecksCurrentDirectoryWithoutCreatingTheFile) {
    const fs::path name = "vkwater_image_path_check_probe.out";
    ASSERT_FALSE(fs::exists(name));
    EXPECT_NO_THROW(require_writable_file_path(name));
    EXPECT_FALSE(fs::exists(name));
}

}  // namespace
}  // namespace vkw
