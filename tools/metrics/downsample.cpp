// Box downsampling of images and masks (definitions in downsample.hpp).
#include "tools/metrics/downsample.hpp"

#include <algorithm>
#include <string>

#include "engine/core/errors.hpp"
#include "tools/metrics/rgb_view.hpp"

namespace vkw::metrics {
namespace {

void require_factor(const ImageRGBA32F& image, int factor) {
    require_consistent_image(image);
    const int largest = std::min(image.width, image.height);
    if (factor < 1 || factor > largest) {
        throw UserError("downsampling factor " + std::to_string(factor) + " is out of range for a " +
                        size_text(image.width, image.height) + " image (accepted: 1 to " + std::to_string(largest) +
                        ")");
    }
}

// The block means of one interleaved plane of `channels` floats per pixel.
std::vector<float> downsample_plane(const std::vector<float>& values, int width, int channels, int factor,
                                    int out_width, int out_height) {
    std::vector<float> out(static_cast<std::size_t>(out_width) * static_cast<std::size_t>(out_height) *
                           static_cast<std::size_t>(channels));
    const double block_pixels = static_cast<double>(factor) * factor;
    for (int by = 0; by < out_height; ++by) {
        for (int bx = 0; bx < out_width; ++bx) {
            for (int c = 0; c < channels; ++c) {
                // factor^2 float terms summed in double: the sum's rounding stays far below the
                // float rounding the mean gets once at the end.
                double sum = 0.0;
                for (int y = by * factor; y < (by + 1) * factor; ++y) {
                    for (int x = bx * factor; x < (bx + 1) * factor; ++x) {
                        sum += values[(static_cast<std::size_t>(y) * static_cast<std::size_t>(width) +
                                       static_cast<std::size_t>(x)) *
                                          static_cast<std::size_t>(channels) +
                                      static_cast<std::size_t>(c)];
                    }
                }
                const std::size_t out_pixel =
                    static_cast<std::size_t>(by) * static_cast<std::size_t>(out_width) + static_cast<std::size_t>(bx);
                out[out_pixel * static_cast<std::size_t>(channels) + static_cast<std::size_t>(c)] =
                    static_cast<float>(sum / block_pixels);
            }
        }
    }
    return out;
}

}  // namespace

ImageRGBA32F box_downsample(const ImageRGBA32F& image, int factor) {
    require_factor(image, factor);
    ImageRGBA32F out;
    out.width = image.width / factor;
    out.height = image.height / factor;
    out.rgba = downsample_plane(image.rgba, image.width, 4, factor, out.width, out.height);
    for (const ExtraLayer& layer : image.layers) {
        out.layers.push_back(
            ExtraLayer{layer.name, downsample_plane(layer.rgb, image.width, 3, factor, out.width, out.height)});
    }
    return out;
}

ImageRGBA32F box_downsample_mask(const ImageRGBA32F& mask, int factor) {
    require_factor(mask, factor);
    ImageRGBA32F selected = mask;
    selected.layers.clear();
    // 1 for a selected pixel, 0 otherwise: the block mean is 1 exactly when all are selected
    // (a sum of at most 64^2 ones is exact in double).
    for (std::size_t p = 0; p < selected.pixel_count(); ++p) {
        const float value = mask.rgba[p * 4] > 0.5f ? 1.0f : 0.0f;
        std::fill_n(selected.rgba.begin() + static_cast<std::ptrdiff_t>(p * 4), 4, value);
    }
    ImageRGBA32F out = box_downsample(selected, factor);
    for (float& value : out.rgba) value = value == 1.0f ? 1.0f : 0.0f;
    return out;
}

}  // namespace vkw::metrics
