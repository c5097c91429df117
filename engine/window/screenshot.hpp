// A screenshot of the window: the frame's linear HDR as OpenEXR (32-bit float, as `vkwater
// render` writes it, so the two compare exactly) and the picture the window showed as PNG
// beside it (the same exposure, ACES and sRGB chain, engine/image/png_preview).
#pragma once

#include "engine/image/image.hpp"

#include <cstdint>
#include <filesystem>
#include <vector>

namespace vkw::window {

// `rgba`: width x height RGBA 32-bit float texels, row 0 at the top (the hand-off image as
// read back). `attributes` go into the EXR's header. Returns the PNG's path: `exr` with the
// extension .png.
std::filesystem::path write_screenshot(const std::filesystem::path& exr, const float* rgba, uint32_t width,
                                       uint32_t height, float exposure, std::vector<ImageAttribute> attributes);

}  // namespace vkw::window
