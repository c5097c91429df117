// The RGB values a metric compares (the main image's R, G, B or one extra layer), the set of
// pixels that count (all, or those a mask selects) and the input checks every metric shares.
#pragma once

#include <cstddef>
#include <span>
#include <string>
#include <vector>

#include "engine/image/image.hpp"

namespace vkw::metrics {

// A read-only view of width x height RGB triples, `stride` floats apart. Alpha is never read:
// the metrics compare radiance, and the renderer's alpha carries no light.
struct RgbView {
    int width = 0;
    int height = 0;
    const float* values = nullptr;
    int stride = 4;  // 4 for the RGBA of ImageRGBA32F, 3 for an ExtraLayer's rgb

    std::size_t pixel_count() const { return static_cast<std::size_t>(width) * static_cast<std::size_t>(height); }
    // Channel c (0 = R, 1 = G, 2 = B) of pixel p (row-major index).
    double channel(std::size_t p, int c) const { return values[p * static_cast<std::size_t>(stride) + c]; }
};

RgbView rgb_view(const ImageRGBA32F& image);

// Throws UserError naming `image_name`, the layer and the layers the image has when it has no
// such layer.
RgbView layer_view(const ImageRGBA32F& image, const std::string& layer, const std::string& image_name = "the image");

// Row-major indices of the pixels that count: every pixel without a mask, otherwise those
// whose mask R is > 0.5 (so a 0/1 mask works whatever the file's pixel type).
// Throws UserError if the mask's size differs from width x height or it selects no pixel.
std::vector<std::size_t> counted_pixels(int width, int height, const ImageRGBA32F* mask);

// Throws UserError unless test and reference have the same non-empty size and every RGB value
// of both is finite (a NaN would poison every mean and every FLIP filter around it).
void require_comparable(const RgbView& test, const RgbView& reference);

// The same, and `pixels` is non-empty with every index inside the image.
void require_comparable(const RgbView& test, const RgbView& reference, std::span<const std::size_t> pixels);

// Mean of R, G and B over `pixels` (each pixel's three values weigh alike), summed with
// compensation.
double mean_rgb(const RgbView& view, std::span<const std::size_t> pixels);

// "WxH", for messages.
std::string size_text(int width, int height);

}  // namespace vkw::metrics
