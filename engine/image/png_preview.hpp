// An 8-bit sRGB PNG of an HDR image, for looking at a render without an EXR viewer.
#pragma once

#include <cstddef>
#include <filesystem>

#include "engine/image/image.hpp"

namespace vkw {

// Writes the RGB channels (alpha dropped: the preview shows radiance, and viewers would
// otherwise draw transparent water over a checkerboard) as value * exposure -> ACES filmic ->
// sRGB -> 8 bit with a triangular dither keyed by the pixel (tone_curve.hpp: each value within one
// level of the undithered one; the same image gives the same bytes), with an sRGB chunk. Pixels
// with any non-finite R, G or B are drawn magenta; returns how many.
// Throws UserError for an unwritable path or an exposure that is not finite and > 0,
// InternalError if the image's sizes are inconsistent.
std::size_t write_png_preview(const std::filesystem::path& path, const ImageRGBA32F& image, float exposure);

}  // namespace vkw
