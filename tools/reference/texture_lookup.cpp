// Bilinear base colour lookup of the reference renderer (see texture_lookup.hpp).
#include "tools/reference/texture_lookup.hpp"

#include <algorithm>
#include <array>
#include <cmath>

namespace vkw::ref {
namespace {

// Texel index i of an axis of n texels, mapped into [0, n) as the wrap mode says (glTF's wrap
// modes are OpenGL's, which Vulkan's address modes match).
int64_t wrapped(int64_t i, int64_t n, TextureWrap wrap) {
    switch (wrap) {
        case TextureWrap::ClampToEdge: return i < 0 ? 0 : (i >= n ? n - 1 : i);
        case TextureWrap::MirroredRepeat: {
            const int64_t m = ((i % (2 * n)) + 2 * n) % (2 * n);
            return m < n ? m : 2 * n - 1 - m;
        }
        case TextureWrap::Repeat: break;
    }
    return ((i % n) + n) % n;
}

}  // namespace

double srgb_to_linear(uint8_t encoded) {
    static const std::array<double, 256> table = [] {
        std::array<double, 256> values{};
        for (int i = 0; i < 256; ++i) {
            const double c = i / 255.0;
            values[std::size_t(i)] = c <= 0.04045 ? c / 12.92 : std::pow((c + 0.055) / 1.055, 2.4);
        }
        return values;
    }();
    return table[encoded];
}

glm::dvec4 bilinear_base_color(const MeshTexture& texture, const glm::dvec2& uv) {
    const TextureImage& image = *texture.image;
    const auto width = int64_t(image.width), height = int64_t(image.height);
    // Texel centres sit at half-integers: the four around the point and its weights between them.
    // Coordinates far outside [0, 1] (a repeating pattern) are reduced first, keeping the
    // fraction exact enough for the index arithmetic.
    const auto reduce = [](double t) { return std::isfinite(t) ? t - 2.0 * std::floor(t / 2.0) : 0.0; };
    const bool repeats_u = texture.wrap_u != TextureWrap::ClampToEdge;
    const bool repeats_v = texture.wrap_v != TextureWrap::ClampToEdge;
    const double x = (repeats_u ? reduce(uv.x) : std::clamp(uv.x, -1.0, 2.0)) * double(width) - 0.5;
    const double y = (repeats_v ? reduce(uv.y) : std::clamp(uv.y, -1.0, 2.0)) * double(height) - 0.5;
    const double x0 = std::floor(x), y0 = std::floor(y);
    const double fx = x - x0, fy = y - y0;
    const auto texel = [&](int64_t i, int64_t j) {
        const std::size_t at =
            4 * std::size_t(wrapped(j, height, texture.wrap_v) * width + wrapped(i, width, texture.wrap_u));
        return glm::dvec4(srgb_to_linear(image.rgba[at]), srgb_to_linear(image.rgba[at + 1]),
                          srgb_to_linear(image.rgba[at + 2]), image.rgba[at + 3] / 255.0);
    };
    const auto i = int64_t(x0), j = int64_t(y0);
    return (1.0 - fy) * ((1.0 - fx) * texel(i, j) + fx * texel(i + 1, j)) +
           fy * ((1.0 - fx) * texel(i, j + 1) + fx * texel(i + 1, j + 1));
}

}  // namespace vkw::ref
