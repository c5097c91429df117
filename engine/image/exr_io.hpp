// Reading and writing ImageRGBA32F as OpenEXR (linear R, G, B, A plus "<layer>.R/G/B").
#pragma once

#include <cstddef>
#include <filesystem>
#include <span>

#include "engine/image/image.hpp"

namespace vkw {

enum class ExrPixelType { Float, Half };

// What write_exr had to do to the data; the caller decides how to tell the user.
struct ExrWriteReport {
    std::size_t clamped_values = 0;    // Half only: finite values with |v| > 65504, stored as +-65504
    std::size_t nonfinite_values = 0;  // NaN / +-inf, stored unchanged
};

// Writes R, G, B, A and "<layer>.R/G/B" for each extra layer, ZIP-compressed, with the standard
// `chromaticities` attribute (Rec. 709 primaries, D65 white: the renderers' linear RGB) and each of
// the image's attributes as a string attribute. The output is deterministic: the same image
// (attributes included) and pixel type give a byte-identical file.
// Throws UserError (one line naming the path) if the file cannot be written,
// InternalError if the image's sizes are inconsistent.
ExrWriteReport write_exr(const std::filesystem::path& path, const ImageRGBA32F& image,
                         ExrPixelType pixel_type = ExrPixelType::Float);

// Reads R, G, B (required) and A (1 where missing), half, float or uint, plus every layer
// that has any of "<name>.R/G/B" (missing ones read as 0); layers come back sorted by name, and
// the header's string attributes as attributes, sorted by name.
// The data window's top-left corner becomes pixel (0, 0).
// Throws UserError (one line naming the path) for a missing, unreadable, corrupt or truncated file,
// and for one that declares more than 16384 pixels a side (refused before any pixel is allocated).
ImageRGBA32F read_exr(const std::filesystem::path& path);

// The same for a file's bytes already in memory (read_exr reads the file into memory once and
// calls this); `name` stands for the file in messages.
ImageRGBA32F read_exr_bytes(std::span<const char> bytes, const std::filesystem::path& name);

}  // namespace vkw
