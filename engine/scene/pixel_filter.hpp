// How an image's pixels sample the scene: at their centres (a point filter, one sample per pixel)
// or averaged over k x k samples spread over the pixel's square (a box filter, --spp N = k^2).
// Both renderers take it: the reference as k x k stratified samples jittered within their strata,
// different per pixel and the same every run; the real-time renderer as k^2 sub-frames, each
// shifted by one stratum's centre for every pixel at once, averaged in float.
#pragma once

#include <glm/glm.hpp>

#include <cstdint>
#include <string>

namespace vkw {

struct PixelFilter {
    uint32_t samples = 1;  // N = side^2 samples per pixel; 1: the pixel's centre

    uint32_t side() const;  // k
    bool is_box() const { return samples > 1; }
    // As the EXR attribute vkwater/filter records it: "point: one sample at each pixel centre" or
    // "box: N samples per pixel (k x k strata)".
    std::string describe() const;
    // Sample i (0 .. N - 1) as an offset from the pixel's centre, in pixels, each coordinate in
    // (-0.5, 0.5): the centre of stratum i ...
    glm::dvec2 stratum_centre(uint32_t i) const;
    // ... or a point of stratum i hashed from the pixel (x, y) and i (the reference's).
    glm::dvec2 jittered_sample(uint32_t x, uint32_t y, uint32_t i) const;
};

// The filter of `--spp N`: N a perfect square from 1 to 256; anything else is a vkw::UserError
// naming the option, the value and the accepted ones.
PixelFilter pixel_filter_from_spp(int64_t spp);

// The filter's kind ("point" or "box") from a vkwater/filter attribute's text; empty when the
// text names neither.
std::string pixel_filter_kind(const std::string& attribute);

// The NDC shift of the image plane (Camera::image_shift_ndc) that makes each pixel's centre show
// the ray through its centre plus `pixel_offset` (pixels, x right, y down) in a width x height image.
glm::dvec2 image_shift_for_pixel_offset(glm::dvec2 pixel_offset, uint32_t width, uint32_t height);

}  // namespace vkw
