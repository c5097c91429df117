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
        const std::uint32_t value = word_at(at);
        at += 4;
        return value;
    }
    std::uint32_t word_at(std::size_t i) const {
        std::uint32_t value = 0;
        for (int k = 0; k < 4; ++k) value |= std::uint32_t(static_cast<unsigned char>(file[i + k])) << (8 * k);
        return value;
    }
};

// What a single-part scanline header says about its uncompressed lines: the data window's width
// and height and the bytes of one line. Filled from the attributes as the walk passes them.
struct LineLayout {
    bool uncompressed = false;
    bool channels_known = false;  // a channel list that parses, every channel at full resolution
    std::int64_t width = 0, height = 0;
    std::uint64_t pixel_bytes = 0;  // the bytes of one pixel over every channel
};

void note_attribute(LineLayout& layout, const std::string& name, const std::string& type, std::span<const char> value,
                    const ByteReader& in) {
    const auto word = [&](std::size_t i) {
        return static_cast<std::int32_t>(in.word_at(static_cast<std::size_t>(value.data() - in.file.data()) + i));
    };
    if (name == "compression" && type == "compression" && value.size() == 1) {
        layout.uncompressed = value[0] == 0;
    } else if (name == "dataWindow" && type == "box2i" && value.size() == 16) {
        layout.width = std::int64_t{word(8)} - word(0) + 1;
        layout.height = std::int64_t{word(12)} - word(4) + 1;
    } else if (name == "channels" && type == "chlist") {
        // Each channel: name\0, int32 pixel type (0 uint, 1 half, 2 float), uint8 linear, 3
        // reserved bytes, int32 x and y sampling; an empty name ends the list.
        layout.pixel_bytes = 0;
        std::size_t i = 0;
        while (i < value.size() && value[i] != '\0') {
            while (i < value.size() && value[i] != '\0') ++i;
            if (value.size() - i < 17) return;
            const std::int32_t kind = word(i + 1), x_sampling = word(i + 9), y_sampling = word(i + 13);
            if (kind < 0 || kind > 2 || x_sampling != 1 || y_sampling != 1) return;
            layout.pixel_bytes += kind == 1 ? 2 : 4;
            i += 17;
        }
        layout.channels_known = i < value.size();
    }
}

// In an uncompressed single-part scanline file every line is one chunk of exactly its bytes.
// OpenEXR's reader takes a shorter chunk's missing bytes from whatever follows it, and its checker
// lets that pass, so the chunks the offset table points at are checked here. Offsets outside the
// file are left to OpenEXR (it rebuilds a broken table by walking the chunks, or refuses the file).
std::optional<std::string> uncompressed_line_problem(const ByteReader& in, const LineLayout& layout) {
    if (!layout.uncompressed || !layout.channels_known || layout.width <= 0 || layout.height <= 0 ||
        layout.width > (1 << 24) || layout.height > (1 << 24)) {
        return std::nullopt;
    }
    const std::uint64_t line_bytes = static_cast<std::uint64_t>(layout.width) * layout.pixel_bytes;
    const auto table_entries = static_cast<std::uint64_t>(layout.height);
    if (table_entries > in.left() / 8) return std::nullopt;  // a cut-off table: OpenEXR's to judge
    for (std::uint64_t line = 0; line < table_entries; ++line) {
        std::uint64_t offset = 0;
        for (int k = 0; k < 8; ++k) {
            offset |= std::uint64_t(static_cast<unsigned char>(in.file[in.at + 8 * line + k])) << (8 * k);
        }
        if (offset < in.at || offset > in.file.size() || in.file.size() - offset < 8) continue;
        const std::uint32_t size = in.word_at(static_cast<std::size_t>(offset) + 4);
        if (size != line_bytes) {
            return "the chunk of line " + std::to_string(line) + " (at byte " + std::to_string(offset) + ") holds " +
                   std::to_string(static_cast<std::int32_t>(size)) +
                   " bytes, and an uncompressed line of this image takes " + std::to_string(line_bytes);
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
            if (scanlines) note_attribute(layout, *name, *type, value, in);
            if (largest != nullptr && *name == "dataWindow") {
                LineLayout window;  // every part's, multi-part and tiled files' too
                note_attribute(window, *name, *type, value, in);
                if (std::max(window.width, window.height) > std::max(largest->width, largest->height)) {
                    *largest = {window.width, window.height};
                }
            }
            in.at += static_cast<std::size_t>(size);
        }
        if (!multi_part) return std::nullopt;
    }
}

}  // namespace vkw
