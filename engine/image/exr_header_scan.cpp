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
constexpr std::size_t kMagicBytes = 4;

// A cursor over the file's bytes.
struct ByteReader {
    std::span<const char> file;
    std::size_t at = kMagicBytes;

    std::size_t left() const { return file.size() - at; }

    // The name at the cursor, up to its NUL; nullopt if longer than `max_length` or cut off.
    std::optional<std::string> name(std::size_t max_length) {
        std::string name;
        while (at < file.size()) {
            const char c = file[at++];
            if (c == '\0') return name;
            if (name.size() == max_length) return std::nullopt;
            name.push_back(c);
        }
        return std::nullopt;
    }

    // A little-endian 32-bit word at the cursor; nullopt if the file ends first.
    std::optional<std::uint32_t> word() {
        if (left() < 4) {
            at = file.size();
            return std::nullopt;
        }
        std::uint32_t value = 0;
        for (int i = 0; i < 4; ++i) value |= std::uint32_t(static_cast<unsigned char>(file[at + i])) << (8 * i);
        at += 4;
        return value;
    }
};

// `name` as a message shows it: printable ASCII as it is, anything else as '?'.
std::string printable(std::string name) {
    for (char& c : name) {
        if (!std::isprint(static_cast<unsigned char>(c))) c = '?';
    }
    return name;
}

}  // namespace

std::optional<std::string> exr_header_problem(std::span<const char> file) {
    ByteReader in{file};
    if (file.size() < kMagicBytes) return "the version field is cut off";
    const std::optional<std::uint32_t> version = in.word();
    if (!version) return "the version field is cut off";
    const std::size_t max_name = (*version & kLongNamesFlag) ? 255 : 31;
    const bool multi_part = (*version & kMultiPartFlag) != 0;
    int attributes = 0;
    for (int part = 0;; ++part) {
        for (int in_part = 0;; ++in_part) {
            const std::size_t at = in.at;
            const std::optional<std::string> name = in.name(max_name);
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
            const std::optional<std::string> type = in.name(max_name);
            const std::optional<std::uint32_t> size_word = type ? in.word() : std::nullopt;
            if (!size_word) {
                return "attribute '" + printable(*name) + "' (at byte " + std::to_string(at) +
                       ") is cut off before its size";
            }
            const auto size = static_cast<std::int32_t>(*size_word);
            if (size < 0 || static_cast<std::uint64_t>(size) > in.left()) {
                return "attribute '" + printable(*name) + "' (at byte " + std::to_string(at) + ") declares " +
                       std::to_string(size) + " bytes, and " + std::to_string(in.left()) + " are left in the file";
            }
            in.at += static_cast<std::size_t>(size);
        }
        if (!multi_part) return std::nullopt;
    }
}

}  // namespace vkw
