// A walk over an OpenEXR file's header before OpenEXR reads it. OpenEXR allocates the size each
// header attribute declares before it reads the value, so a file of a few bytes that declares a
// 2 GB attribute makes it allocate (and touch) 2 GB: a user's corrupt file could exhaust the
// machine's memory, and every such input cost the EXR fuzzer about 20 ms. The walk reads only the
// attribute names, types and sizes, and skips the values, except the few that say how long an
// uncompressed line is: in such a file OpenEXR's reader takes a short chunk's missing bytes from
// whatever follows it, and its checker lets the file pass, so the walk checks those chunks too.
#pragma once

#include <cstdint>
#include <optional>
#include <span>
#include <string>

namespace vkw {

// What is wrong with the header(s) of the OpenEXR file `file`, all of its bytes (the magic number,
// already checked, included; the walk starts after it): an attribute name or type longer than the format
// allows (31 bytes, or 255 with the long-names flag) or cut off by the end of the file, a declared
// size that is negative or larger than what is left of the file, more attributes than any file
// needs (kMaxExrAttributes), or, in an uncompressed single-part scanline file, a line whose chunk
// (where the offset table points, inside the file) holds other than the line's bytes. nullopt
// when every header ends where the format says it does and every such chunk fits its line.
// `largest`, when given, receives the data window (width and height, in pixels) with the longest
// side over every part's header, so that the caller can refuse an oversized image before OpenEXR
// allocates for it; 0 x 0 when no header has a well-formed dataWindow.
struct ExrWindowSize {
    std::int64_t width = 0, height = 0;
};
std::optional<std::string> exr_header_problem(std::span<const char> file, ExrWindowSize* largest = nullptr);

inline constexpr int kMaxExrAttributes = 100000;

}  // namespace vkw
