// exr_header_problem (exr_header_scan.hpp), after the OpenEXR file layout: the magic number, a
// 4-byte version field (bits 0-7 the version, bit 10 long names, bit 12 multi-part), then the
// header's attributes (name\0 type\0 int32 size, value), ended by an empty name; a multi-part
// file has one header per part and an empty header after the last.
#include "engine/image/exr_header_scan.hpp"

#include <cctype>

namespace vkw {
namespace {

constexpr std::uint32_t kLongNamesFlag = 1u << 10;
constexpr std::uint32_t kMultiPartFlag = 1u << 12;

// The name at the stream's position, up to its NUL; nullopt if longer than `max_length` or cut off.
std::optional<std::string> read_name(std::istream& in, std::size_t max_length) {
    std::string name;
    for (char c; in.get(c);) {
        if (c == '\0') return name;
        if (name.size() == max_length) return std::nullopt;
        name.push_back(c);
    }
    return std::nullopt;
}

// `name` as a message shows it: printable ASCII as it is, anything else as '?'.
std::string printable(std::string name) {
    for (char& c : name) {
        if (!std::isprint(static_cast<unsigned char>(c))) c = '?';
    }
    return name;
}

}  // namespace

std::optional<std::string> exr_header_problem(std::istream& in, std::uint64_t file_bytes) {
    unsigned char version_bytes[4];
    if (!in.read(reinterpret_cast<char*>(version_bytes), 4)) return "the version field is cut off";
    const std::uint32_t version =
        version_bytes[0] | (version_bytes[1] << 8) | (version_bytes[2] << 16) | (std::uint32_t(version_bytes[3]) << 24);
    const std::size_t max_name = (version & kLongNamesFlag) ? 255 : 31;
    const bool multi_part = (version & kMultiPartFlag) != 0;
    int attributes = 0;
    for (int part = 0;; ++part) {
        for (int in_part = 0;; ++in_part) {
            const std::streamoff position = in.tellg();
            if (position < 0) return "the header runs past the end of the file";
            const auto at = static_cast<std::uint64_t>(position);
            const std::optional<std::string> name = read_name(in, max_name);
            if (!name) {
                return "the attribute name at byte " + std::to_string(at) + " is cut off or longer than " +
                       std::to_string(max_name) + " bytes";
            }
            if (name->empty()) {
                // The end of a header; in a multi-part file, an empty header ends the list.
                if (!multi_part || in_part == 0) return std::nullopt;
                break;
            }
            if (++attributes > kMaxExrAttributes) {
                return "more than " + std::to_string(kMaxExrAttributes) + " header attributes";
            }
            const std::optional<std::string> type = read_name(in, max_name);
            unsigned char size_bytes[4];
            if (!type || !in.read(reinterpret_cast<char*>(size_bytes), 4)) {
                return "attribute '" + printable(*name) + "' (at byte " + std::to_string(at) +
                       ") is cut off before its size";
            }
            const auto size = static_cast<std::int32_t>(size_bytes[0] | (size_bytes[1] << 8) | (size_bytes[2] << 16) |
                                                        (std::uint32_t(size_bytes[3]) << 24));
            const std::streamoff value_at = in.tellg();
            if (value_at < 0 || static_cast<std::uint64_t>(value_at) > file_bytes) {
                return "the header runs past the end of the file";
            }
            const std::uint64_t left = file_bytes - static_cast<std::uint64_t>(value_at);
            if (size < 0 || static_cast<std::uint64_t>(size) > left) {
                return "attribute '" + printable(*name) + "' (at byte " + std::to_string(at) + ") declares " +
                       std::to_string(size) + " bytes, and " + std::to_string(left) + " are left in the file";
            }
            in.seekg(size, std::ios::cur);
        }
        if (!multi_part) return std::nullopt;
    }
}

}  // namespace vkw
