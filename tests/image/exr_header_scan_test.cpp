// exr_header_problem against headers built byte by byte after the OpenEXR layout: every header of a
// written file passes; sizes past the end of the file, negative sizes, over-long or cut-off names
// and an unterminated multi-part list are each named.
#include "engine/image/exr_header_scan.hpp"
#include "engine/image/exr_io.hpp"
#include "engine/image/image.hpp"

#include <gtest/gtest.h>

#include <cstdint>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <optional>
#include <string>

namespace vkw::test {
namespace {

std::string int32_bytes(std::int32_t value) {
    std::string bytes(4, '\0');
    for (int i = 0; i < 4; ++i) bytes[i] = static_cast<char>((static_cast<std::uint32_t>(value) >> (8 * i)) & 0xff);
    return bytes;
}

std::string attribute(const std::string& name, const std::string& type, const std::string& value) {
    return name + '\0' + type + '\0' + int32_bytes(static_cast<std::int32_t>(value.size())) + value;
}

// The problem of a file that is the magic number, `version`, then `headers`, followed by `tail`
// bytes of pixel data; the scan starts after the magic number, as read_exr has checked it.
std::optional<std::string> problem(std::int32_t version, const std::string& headers, std::size_t tail = 64) {
    const std::string file = "v/1\x01" + int32_bytes(version) + headers + std::string(tail, '\x7f');
    return exr_header_problem(file);
}

constexpr std::int32_t kSinglePart = 2, kLongNames = 2 | (1 << 10), kMultiPart = 2 | (1 << 12);

TEST(ExrHeaderScan, AWrittenFilePasses) {
    ImageRGBA32F image;
    image.width = 7;
    image.height = 5;
    image.rgba.assign(image.pixel_count() * 4, 0.5f);
    image.attributes.push_back({"vkwater/scene", "a string attribute"});
    const std::filesystem::path path = std::filesystem::path(testing::TempDir()) / "exr_header_scan.exr";
    write_exr(path, image);
    std::ifstream in(path, std::ios::binary);
    const std::string file((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    EXPECT_EQ(exr_header_problem(file), std::nullopt);
    std::filesystem::remove(path);
}

TEST(ExrHeaderScan, SizesMustFitTheFile) {
    const std::string box(16, '\0');
    EXPECT_EQ(problem(kSinglePart, attribute("dataWindow", "box2i", box) + '\0'), std::nullopt);
    // The 64 bytes of the tail are left after the size field: a value of 63 bytes fits, and the
    // tail's last byte (0x7f) then starts a name the file cuts off; 65 bytes do not fit.
    const std::string head = std::string("comments") + '\0' + "string" + '\0';
    EXPECT_EQ(problem(kSinglePart, head + int32_bytes(63) + std::string(63, 'v') + '\0', 0), std::nullopt);
    EXPECT_EQ(problem(kSinglePart, head + int32_bytes(63)),
              "the attribute name at byte 91 is cut off or longer than 31 bytes");
    EXPECT_EQ(problem(kSinglePart, head + int32_bytes(65)),
              "attribute 'comments' (at byte 8) declares 65 bytes, and 64 are left in the file");
    EXPECT_EQ(problem(kSinglePart, head + int32_bytes(-1)),
              "attribute 'comments' (at byte 8) declares -1 bytes, and 64 are left in the file");
    EXPECT_EQ(problem(kSinglePart, head + int32_bytes(2000000000)),
              "attribute 'comments' (at byte 8) declares 2000000000 bytes, and 64 are left in the file");
}

TEST(ExrHeaderScan, NamesAreAtMost31BytesUnlessLongNamesAreOn) {
    const std::string name32(32, 'n');
    EXPECT_EQ(problem(kSinglePart, attribute(name32, "float", "abcd") + '\0'),
              "the attribute name at byte 8 is cut off or longer than 31 bytes");
    EXPECT_EQ(problem(kLongNames, attribute(name32, "float", "abcd") + '\0'), std::nullopt);
    EXPECT_EQ(problem(kSinglePart, std::string("unterminated"), 0),
              "the attribute name at byte 8 is cut off or longer than 31 bytes");
}

TEST(ExrHeaderScan, MultiPartHeadersEndWithAnEmptyHeader) {
    const std::string part = attribute("name", "string", "left") + '\0';
    EXPECT_EQ(problem(kMultiPart, part + part + '\0'), std::nullopt);
    // Without the empty header the scan runs into the pixel data, whose bytes make no name.
    EXPECT_NE(problem(kMultiPart, part + part, 0), std::nullopt);
}

}  // namespace
}  // namespace vkw::test
