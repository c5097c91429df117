// compare_images / compare_layer: every metric of one pair, over the same counted pixels.
#include "tools/metrics/metrics.hpp"

#include <vector>

namespace vkw::metrics {
namespace {

Metrics compare_views(const RgbView& test, const RgbView& reference, const ImageRGBA32F* mask,
                      const FlipExposureRange* range) {
    const std::vector<std::size_t> pixels = counted_pixels(reference.width, reference.height, mask);
    require_comparable(test, reference, pixels);  // before the exposure range reads the reference
    const FlipExposureRange exposures = range != nullptr ? *range : flip_exposure_range(reference);
    Metrics metrics;
    metrics.rel_mse = rel_mse(test, reference, pixels);
    metrics.flip_mean = flip_mean(test, reference, pixels, exposures);
    metrics.bias = mean_bias(test, reference, pixels);
    metrics.luv_mean = luv_mean_distance(test, reference, pixels);
    return metrics;
}

}  // namespace

Metrics compare_images(const ImageRGBA32F& test, const ImageRGBA32F& reference, const ImageRGBA32F* mask,
                       const FlipExposureRange* range) {
    return compare_views(rgb_view(test), rgb_view(reference), mask, range);
}

Metrics compare_layer(const ImageRGBA32F& test, const ImageRGBA32F& reference, const std::string& layer,
                      const ImageRGBA32F* mask, const FlipExposureRange* range) {
    return compare_views(layer_view(test, layer, "the test image"), layer_view(reference, layer, "the reference"), mask,
                         range);
}

}  // namespace vkw::metrics
