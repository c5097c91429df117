// PNG preview writer: tone maps with tone_curve.hpp and encodes with stb_image_write.
#include "engine/image/png_preview.hpp"

// Debian's libstb is a compiled library: include the declarations only, no *_IMPLEMENTATION.
#include <stb_image_write.h>
#include <zlib.h>

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

// The sRGB chunk (PNG 1.2, 11.3.3.5) after IHDR: the pixels are sRGB-encoded, rendering intent 0
// (perceptual), so colour-managed viewers show them as meant. stb_image_write writes no such chunk.
void insert_srgb_chunk(std::string& png) {
    constexpr std::size_t kAfterIhdr = 8 + 4 + 4 + 13 + 4;  // signature, IHDR's length, type, data, CRC
    if (png.size() < kAfterIhdr || png.compare(12, 4, "IHDR") != 0) {
        throw InternalError("PNG preview: the encoder's output does not start with IHDR");
    }
    const unsigned char type_and_data[] = {'s', 'R', 'G', 'B', 0};
    const uLong crc = crc32(crc32(0L, Z_NULL, 0), type_and_data, sizeof type_and_data);
    std::string chunk = {0, 0, 0, 1};
    chunk.append(reinterpret_cast<const char*>(type_and_data), sizeof type_and_data);
    for (int shift = 24; shift >= 0; shift -= 8) chunk += static_cast<char>((crc >> shift) & 0xffu);
    png.insert(kAfterIhdr, chunk);
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

    // Row 0 is the top row in both ImageRGBA32F and PNG, so no flip.
    const int row_bytes = image.width * 3;
    // Encoded in memory, then written whole (checked_write.hpp): no partial file under the name.
    std::string bytes;
    auto append = [](void* context, void* data, int size) {
        static_cast<std::string*>(context)->append(static_cast<const char*>(data), static_cast<std::size_t>(size));
    };
    if (stbi_write_png_to_func(append, &bytes, image.width, image.height, 3, rgb8.data(), row_bytes) == 0) {
        throw UserError("cannot write " + quoted_path(path) + ": stbi_write_png_to_func failed to encode");
    }
    insert_srgb_chunk(bytes);
    write_file_checked(path, bytes);
    return nonfinite_pixels;
}

}  // namespace vkw
