// PNG preview writer: tone maps with tone_curve.hpp and encodes with libpng.
#include "engine/image/png_preview.hpp"

#include <png.h>

#include <array>
#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

#include "engine/core/errors.hpp"
#include "engine/image/checked_write.hpp"
#include "engine/image/file_paths.hpp"
#include "engine/image/tone_curve.hpp"

namespace vkw {
namespace {

// Magenta never comes out of the tone curve for a grey-ish water scene, so it stands out.
constexpr std::array<std::uint8_t, 3> kNonFiniteColor = {255, 0, 255};

// Encodes 8-bit RGB rows with libpng's simplified API (no setjmp here: it reports failures through
// its return value). It writes the sRGB chunk for 8-bit data that is not flagged linear, so
// colour-managed viewers show the pixels as meant, and chooses each row's filter adaptively.
std::string encode_png_rgb8(int width, int height, const std::vector<std::uint8_t>& rgb8) {
    png_image png{};
    png.version = PNG_IMAGE_VERSION;
    png.width = static_cast<png_uint_32>(width);
    png.height = static_cast<png_uint_32>(height);
    png.format = PNG_FORMAT_RGB;
    const png_int_32 row_stride = width * 3;
    png_alloc_size_t size = 0;
    if (!png_image_write_get_memory_size(png, size, 0, rgb8.data(), row_stride, nullptr)) {
        throw InternalError(std::string("PNG preview: libpng could not size the file: ") + png.message);
    }
    std::string bytes(size, '\0');
    if (!png_image_write_to_memory(&png, bytes.data(), &size, 0, rgb8.data(), row_stride, nullptr)) {
        throw InternalError(std::string("PNG preview: libpng could not encode the image: ") + png.message);
    }
    bytes.resize(size);
    return bytes;
}

}  // namespace

std::size_t write_png_preview(const std::filesystem::path& path, const ImageRGBA32F& image, float exposure) {
    if (!std::isfinite(exposure) || exposure <= 0.0f) {
        throw UserError("PNG preview exposure must be a finite number > 0, got " + std::to_string(exposure));
    }
    require_consistent_image(image);
    require_writable_file_path(path);

    const std::size_t pixels = image.pixel_count();
    std::vector<std::uint8_t> rgb8(pixels * 3);
    std::size_t nonfinite_pixels = 0;
    for (std::size_t i = 0; i < pixels; ++i) {
        const float* in = &image.rgba[i * 4];
        std::uint8_t* out = &rgb8[i * 3];
        if (!std::isfinite(in[0]) || !std::isfinite(in[1]) || !std::isfinite(in[2])) {
            std::copy(kNonFiniteColor.begin(), kNonFiniteColor.end(), out);
            ++nonfinite_pixels;
            continue;
        }
        // Dithered before the 8-bit rounding: smooth gradients (a calm sky, deep water) band
        // without it.
        const auto x = static_cast<std::uint32_t>(i % static_cast<std::size_t>(image.width));
        const auto y = static_cast<std::uint32_t>(i / static_cast<std::size_t>(image.width));
        for (int c = 0; c < 3; ++c) {
            out[c] = to_unorm8_dithered(linear_to_srgb(aces_narkowicz(in[c] * exposure)), x, y,
                                        static_cast<std::uint32_t>(c));
        }
    }

    // Row 0 is the top row in both ImageRGBA32F and PNG, so no flip. Encoded in memory, then
    // written whole (checked_write.hpp): no partial file under the name.
    write_file_checked(path, encode_png_rgb8(image.width, image.height, rgb8));
    return nonfinite_pixels;
}

}  // namespace vkw
