// The reference's base colour texture lookup (docs/model.md section 4): the image's base level,
// filtered bilinearly in linear RGB (each texel sRGB-decoded first) with the sampler's wrap mode,
// at the exact texture coordinates of each of the reference's samples. It shares nothing with the
// real-time path, whose mip-mapping and sampler filtering are part of its measured error.
#pragma once

#include <glm/glm.hpp>

#include "engine/scene/mesh.hpp"

namespace vkw::ref {

// sRGB-encoded 8-bit value to linear, by IEC 61966-2-1's piecewise curve.
double srgb_to_linear(uint8_t encoded);

// Linear RGB and alpha of `texture` at texture coordinates `uv` ((0, 0) the image's top-left
// corner, (1, 1) its bottom-right), in [0, 1] per channel (alpha is stored linear: not decoded).
glm::dvec4 bilinear_base_color(const MeshTexture& texture, const glm::dvec2& uv);

}  // namespace vkw::ref
