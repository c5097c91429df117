#include "engine/scene/pixel_filter.hpp"

#include "engine/core/errors.hpp"

#include <algorithm>
#include <cmath>

namespace vkw {

namespace {

constexpr uint32_t kMaxSamples = 256;

// Steele, Lea and Flood's SplitMix64 finaliser: a well-mixed 64-bit value from its input.
uint64_t mix64(uint64_t z) {
    z += 0x9e3779b97f4a7c15ull;
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
    return z ^ (z >> 31);
}

}  // namespace

uint32_t PixelFilter::side() const { return static_cast<uint32_t>(std::lround(std::sqrt(double(samples)))); }

std::string PixelFilter::describe() const {
    if (!is_box()) return "point: one sample at each pixel centre";
    const std::string k = std::to_string(side());
    return "box: " + std::to_string(samples) + " samples per pixel (" + k + " x " + k + " strata)";
}

glm::dvec2 PixelFilter::stratum_centre(uint32_t i) const {
    const uint32_t k = side();
    return (glm::dvec2(i % k, i / k) + 0.5) / double(k) - 0.5;
}

glm::dvec2 PixelFilter::jittered_sample(uint32_t x, uint32_t y, uint32_t i) const {
    const uint32_t k = side();
    const uint64_t h = mix64((uint64_t{x} << 40) ^ (uint64_t{y} << 16) ^ i);
    // 24 bits each: exact in a double, strictly inside [0, 1).
    const glm::dvec2 in_stratum = glm::dvec2(double(h >> 40), double((h >> 16) & 0xffffffull)) / 16777216.0;
    return (glm::dvec2(i % k, i / k) + in_stratum) / double(k) - 0.5;
}

PixelFilter pixel_filter_from_spp(int64_t spp) {
    const int64_t k = std::llround(std::sqrt(double(std::max<int64_t>(spp, 0))));
    if (spp < 1 || spp > kMaxSamples || k * k != spp) {
        throw UserError("--spp " + std::to_string(spp) +
                        ": not a square number of samples per pixel (accepted: 1, 4, 9, 16, ... 256; 1 is the "
                        "pixel's centre)");
    }
    return PixelFilter{static_cast<uint32_t>(spp)};
}

std::string pixel_filter_kind(const std::string& attribute) {
    for (const char* kind : {"point", "box"}) {
        const std::string prefix = std::string(kind) + ":";
        if (attribute.compare(0, prefix.size(), prefix) == 0) return kind;
    }
    return "";
}

glm::dvec2 image_shift_for_pixel_offset(glm::dvec2 pixel_offset, uint32_t width, uint32_t height) {
    // NDC x runs with the image's x and NDC y against its rows (camera_ray's convention); moving the
    // image plane by -d makes each pixel show what lay d further along.
    return {-2.0 * pixel_offset.x / double(width), 2.0 * pixel_offset.y / double(height)};
}

}  // namespace vkw
