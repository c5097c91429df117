// write_file_checked (engine/image/checked_write.hpp) and the writers that use it: whole files or
// none under the final name, devices written in place, every failure a UserError naming the path.
#include <gtest/gtest.h>

#include <sys/stat.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "engine/core/errors.hpp"
#include "engine/image/checked_write.hpp"
#include "engine/image/exr_io.hpp"
#include "engine/image/png_preview.hpp"
#include "tests/image/image_test_support.hpp"

namespace vkw {
namespace {

namespace fs = std::filesystem;
using test::ScratchDir;

std::string contents(const fs::path& path) {
    std::ifstream in(path, std::ios::binary);
    std::ostringstream text;
    text << in.rdbuf();
    return text.str();
}

// The folder's entries: after a write, only the final file (no temporary left behind).
int entries(const fs::path& folder) {
    int count = 0;
    for ([[maybe_unused]] const fs::directory_entry& entry : fs::directory_iterator(folder)) ++count;
    return count;
}

TEST(image_checked_write, WritesTheWholeFileAndLeavesNoTemporary) {
    ScratchDir dir;
    const fs::path path = dir / "out.txt";
    const std::string bytes(100000, 'x');
    write_file_checked(path, bytes);
    EXPECT_EQ(contents(path), bytes);
    EXPECT_EQ(entries(dir.path()), 1);
}

TEST(image_checked_write, ReplacesAnExistingFileAndKeepsItsMode) {
    ScratchDir dir;
    const fs::path path = dir / "out.txt";
    test::write_text(path, "old contents, longer than the new ones");
    ::chmod(path.c_str(), 0640);
    write_file_checked(path, "new");
    EXPECT_EQ(contents(path), "new");
    struct stat status {};
    ASSERT_EQ(::stat(path.c_str(), &status), 0);
    EXPECT_EQ(status.st_mode & 07777, 0640u);
    EXPECT_EQ(entries(dir.path()), 1);
}

TEST(image_checked_write, ASymbolicLinkKeepsPointingAtTheReplacedFile) {
    ScratchDir dir;
    const fs::path target = dir / "target.txt", link = dir / "link.txt";
    test::write_text(target, "old");
    fs::create_symlink(target, link);
    write_file_checked(link, "new");
    EXPECT_TRUE(fs::is_symlink(link));
    EXPECT_EQ(contents(target), "new");
}

TEST(image_checked_write, DeviceNullIsWrittenInPlace) {
    EXPECT_NO_THROW(write_file_checked("/dev/null", "bytes nobody reads"));
    EXPECT_TRUE(fs::is_character_file("/dev/null"));  // not renamed over
}

// /dev/full accepts the open and fails every write with ENOSPC: the failure a full disk gives.
TEST(image_checked_write, AFullDeviceIsAUserErrorNamingThePath) {
    ASSERT_TRUE(fs::exists("/dev/full"));
    test::expect_user_error([] { write_file_checked("/dev/full", "bytes"); }, "/dev/full", "No space left on device");
    const ImageRGBA32F image = test::make_test_image(4, 3);
    test::expect_user_error([&] { write_exr("/dev/full", image); }, "/dev/full", "No space left on device");
    test::expect_user_error([&] { write_png_preview("/dev/full", image, 1.0f); }, "/dev/full",
                            "No space left on device");
    EXPECT_TRUE(fs::is_character_file("/dev/full"));
}

// The EXR written through memory is the file OpenEXR writes itself: read back, the same pixels.
TEST(image_checked_write, TheExrRoundTrips) {
    ScratchDir dir;
    const fs::path path = dir / "image.exr";
    const ImageRGBA32F image = test::make_test_image(5, 4);
    write_exr(path, image);
    const ImageRGBA32F back = read_exr(path);
    EXPECT_EQ(back.rgba, image.rgba);
    EXPECT_EQ(entries(dir.path()), 1);
}

}  // namespace
}  // namespace vkw
