#include "passes/receivers/texture_mips.hpp"

#include <algorithm>
#include <array>
#include <cmath>

#include <glm/gtc/packing.hpp>

namespace vkw::passes {
namespace {

// IEC 61966-2-1's decoding curve, per 8-bit value.
const std::array<float, 256>& srgb_table() {
    static const std::array<float, 256> table = [] {
        std::array<float, 256> values{};
        for (int i = 0; i < 256; ++i) {
            const double c = i / 255.0;
            values[std::size_t(i)] = float(c <= 0.04045 ? c / 12.92 : std::pow((c + 0.055) / 1.055, 2.4));
        }
        return values;
    }();
    return table;
}

struct LinearLevel {
    uint32_t width = 0, height = 0;
    std::vector<float> rgba;
};

LinearLevel half_of(const LinearLevel& above) {
    LinearLevel level{std::max(1u, above.width / 2), std::max(1u, above.height / 2), {}};
    level.rgba.resize(4 * std::size_t(level.width) * level.height);
    for (uint32_t y = 0; y < level.height; ++y) {
        for (uint32_t x = 0; x < level.width; ++x) {
            for (uint32_t dy = 0; dy < 2; ++dy) {
                for (uint32_t dx = 0; dx < 2; ++dx) {
                    const uint32_t sx = std::min(2 * x + dx, above.width - 1);
                    const uint32_t sy = std::min(2 * y + dy, above.height - 1);
                    for (std::size_t c = 0; c < 4; ++c) {
                        level.rgba[4 * (std::size_t(y) * level.width + x) + c] +=
                            0.25f * above.rgba[4 * (std::size_t(sy) * above.width + sx) + c];
                    }
                }
            }
        }
    }
    return level;
}

MipLevel as_half(const LinearLevel& level) {
    MipLevel out{level.width, level.height, std::vector<uint16_t>(level.rgba.size())};
    // glm's conversion rounds to nearest (ties away from zero): within half an ulp, 2^-11 relative.
    std::transform(level.rgba.begin(), level.rgba.end(), out.rgba.begin(), glm::packHalf1x16);
    return out;
}

}  // namespace

std::vector<MipLevel> linear_mip_chain(const TextureImage& image) {
    const std::array<float, 256>& decode = srgb_table();
    LinearLevel level{image.width, image.height, std::vector<float>(image.rgba.size())};
    for (std::size_t i = 0; i < image.rgba.size(); ++i) {
        level.rgba[i] = i % 4 == 3 ? image.rgba[i] / 255.0f : decode[image.rgba[i]];  // alpha is linear
    }
    std::vector<MipLevel> levels{as_half(level)};
    while (level.width > 1 || level.height > 1) {
        level = half_of(level);
        levels.push_back(as_half(level));
    }
    return levels;
}

}  // namespace vkw::passes
