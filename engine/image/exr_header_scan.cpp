// exr_header_problem (exr_header_scan.hpp), after the OpenEXR file layout: the magic number, a
// 4-byte version field (bits 0-7 the version, bit 10 long names, bit 12 multi-part), then the
// header's attributes (name\0 type\0 int32 size, value), ended by an empty name; a multi-part
// file has one header per part and an empty header after the last.
#include "engine/image/exr_header_scan.hpp"

#include <algorithm>
#include <cctype>

namespace vkw {
namespace {

constexpr std::uint32_t kLongNamesFlag = 1u << 10;
constexpr std::uint32_t kMultiPartFlag = 1u << 12;
constexpr std::uint32_t kTiledFlag = 1u << 9;
constexpr std::size_t kMagicBytes = 4;

// The little-endian unsigned integer of `bytes` bytes at `at` (the caller checked they are there).
std::uint64_t little_endian(std::span<const char> data, std::size_t at, int bytes) {
    std::uint64_t value = 0;
    for (int k = 0; k < bytes; ++k) value |= std::uint64_t(static_cast<unsigned char>(data[at + k])) << (8 * k);
    return value;
}

std::int32_t int32_at(std::span<const char> data, std::size_t at) {
    return static_cast<std::int32_t>(static_cast<std::uint32_t>(little_endian(data, at, 4)));
}

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
        at += 4;
        return static_cast<std::uint32_t>(little_endian(file, at - 4, 4));
    }
};

// A box2i value's width and height: x_min, y_min, x_max, y_max as int32.
ExrWindowSize window_size(std::span<const char> box) {
    return {std::int64_t{int32_at(box, 8)} - int32_at(box, 0) + 1,
            std::int64_t{int32_at(box, 12)} - int32_at(box, 4) + 1};
}

// The bytes of one pixel over every channel of a chlist value, nullopt unless the list parses and
// every channel is at full resolution. Each channel: name\0, int32 pixel type (0 uint, 1 half,
// 2 float), uint8 linear, 3 reserved bytes, int32 x and y sampling; an empty name ends the list.
std::optional<std::uint64_t> pixel_bytes(std::span<const char> list) {
    std::uint64_t bytes = 0;
    std::size_t i = 0;
    while (i < list.size() && list[i] != '\0') {
        while (i < list.size() && list[i] != '\0') ++i;
        if (list.size() - i < 17) return std::nullopt;
        const std::int32_t kind = int32_at(list, i + 1);
        if (kind < 0 || kind > 2 || int32_at(list, i + 9) != 1 || int32_at(list, i + 13) != 1) return std::nullopt;
        bytes += kind == 1 ? 2 : 4;
        i += 17;
    }
    if (i >= list.size()) return std::nullopt;  // no terminating empty name
    return bytes;
}

// What a single-part scanline header says about its uncompressed lines, filled from the attributes
// as the walk passes them.
struct LineLayout {
    bool uncompressed = false;
    ExrWindowSize window;
    std::optional<std::uint64_t> pixel_bytes;
};

// In an uncompressed single-part scanline file every line is one chunk of exactly its bytes.
// OpenEXR's reader takes a shorter chunk's missing bytes from whatever follows it, and its checker
// lets that pass, so the chunks the offset table points at are checked here. Offsets outside the
// file are left to OpenEXR (it rebuilds a broken table by walking the chunks, or refuses the file).
std::optional<std::string> uncompressed_line_problem(const ByteReader& in, const LineLayout& layout) {
    const auto [width, height] = layout.window;
    if (!layout.uncompressed || !layout.pixel_bytes || width <= 0 || height <= 0 || width > (1 << 24) ||
        height > (1 << 24)) {
        return std::nullopt;
    }
    const std::uint64_t line_bytes = static_cast<std::uint64_t>(width) * *layout.pixel_bytes;
    const auto lines = static_cast<std::uint64_t>(height);
    if (lines > in.left() / 8) return std::nullopt;  // a cut-off table: OpenEXR's to judge
    for (std::uint64_t line = 0; line < lines; ++line) {
        const std::uint64_t offset = little_endian(in.file, in.at + 8 * line, 8);
        if (offset < in.at || offset > in.file.size() || in.file.size() - offset < 8) continue;
        const std::int32_t size = int32_at(in.file, static_cast<std::size_t>(offset) + 4);
        if (size < 0 || static_cast<std::uint64_t>(size) != line_bytes) {
            return "the chunk of line " + std::to_string(line) + " (at byte " + std::to_string(offset) + ") holds " +
                   std::to_string(size) + " bytes, and an uncompressed line of this image takes " +
                   std::to_string(line_bytes);
        }
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

std::optional<std::string> exr_header_problem(std::span<const char> file, ExrWindowSize* largest) {
    ByteReader in{file};
    if (file.size() < kMagicBytes) return "the version field is cut off";
    const std::optional<std::uint32_t> version = in.word();
    if (!version) return "the version field is cut off";
    const std::size_t max_name = (*version & kLongNamesFlag) ? 255 : 31;
    const bool multi_part = (*version & kMultiPartFlag) != 0;
    const bool scanlines = !multi_part && (*version & kTiledFlag) == 0;
    LineLayout layout;
    int attributes = 0;
    while (true) {  // each part's header
        for (int in_part = 0;; ++in_part) {
            const std::size_t at = in.at;
            const std::optional<std::string> name = in.name(max_name);
            if (!name) {
                return "the attribute name at byte " + std::to_string(at) + " is cut off or longer than " +
                       std::to_string(max_name) + " bytes";
            }
            if (name->empty()) {
                // The end of a header; in a multi-part file, an empty header ends the list.
                if (scanlines) return uncompressed_line_problem(in, layout);
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
            const std::span<const char> value = in.file.subspan(in.at, static_cast<std::size_t>(size));
            if (*name == "dataWindow" && *type == "box2i" && size == 16) {
                // Every part's, multi-part and tiled files' too, for `largest`.
                const ExrWindowSize window = window_size(value);
                if (scanlines) layout.window = window;
                if (largest != nullptr &&
                    std::max(window.width, window.height) > std::max(largest->width, largest->height)) {
                    *largest = window;
                }
            } else if (scanlines && *name == "compression" && *type == "compression" && size == 1) {
                layout.uncompressed = value[0] == 0;
            } else if (scanlines && *name == "channels" && *type == "chlist") {
                layout.pixel_bytes = pixel_bytes(value);
            }
            in.at += static_cast<std::size_t>(size);
        }
        if (!multi_part) return std::nullopt;
    }
}

}  // namespace vkw
