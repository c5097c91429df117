// The texels the real-time renderer samples a base colour texture through: every level of its mip
// chain in linear RGBA as 16-bit floats. The image's sRGB bytes are decoded here, on the CPU, by the
// exact curve (a sampler's sRGB decoding may approximate it: lavapipe's is off by up to 2% in dark
// texels); half floats keep every decoded value within 2^-11 relative, and the filtering and the
// mip averages happen in linear colour, so a fine pattern fades to its mean albedo.
#pragma once

#include <cstdint>
#include <vector>

#include "engine/scene/mesh.hpp"

namespace vkw::passes {

struct MipLevel {
    uint32_t width = 0, height = 0;
    std::vector<uint16_t> rgba;  // IEEE half floats, 4 per texel, linear
};

// Level 0 (the image, decoded) and then each level the 2 x 2 box average of the one above, down to
// 1 x 1; each side halves, rounded down, to at least 1; an odd side's last texel is averaged with
// itself.
std::vector<MipLevel> linear_mip_chain(const TextureImage& image);

}  // namespace vkw::passes
