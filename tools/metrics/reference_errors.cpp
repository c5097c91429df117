// The errors of a frame against a reference at full and reduced resolution, and of the
// caustic and in-scatter layers (definitions in reference_errors.hpp).
#include "tools/metrics/reference_errors.hpp"

#include <algorithm>
#include <cstdio>
#include <utility>

#include "tools/metrics/downsample.hpp"

namespace vkw::metrics {
namespace {

bool has_layer(const ImageRGBA32F& image, const std::string& layer) {
    return std::any_of(image.layers.begin(), image.layers.end(),
                       [&](const ExtraLayer& extra) { return extra.name == layer; });
}

}  // namespace

std::string LayerRelMse::text(bool with_reason) const {
    if (!value) return with_reason ? "n/a (" + missing_reason + ")" : "n/a";
    char buffer[32];
    std::snprintf(buffer, sizeof buffer, "%.6g", *value);
    return buffer;
}

LayerRelMse layer_rel_mse(const ImageRGBA32F& test, const ImageRGBA32F& reference, const std::string& layer,
                          const ImageRGBA32F* mask) {
    if (!has_layer(test, layer)) return {std::nullopt, "the test image has no layer '" + layer + "'"};
    if (!has_layer(reference, layer)) return {std::nullopt, "the reference has no layer '" + layer + "'"};
    const RgbView test_view = layer_view(test, layer), reference_view = layer_view(reference, layer);
    const std::vector<std::size_t> pixels = counted_pixels(reference.width, reference.height, mask);
    require_comparable(test_view, reference_view, pixels);
    if (!(mean_rgb(reference_view, pixels) > 0.0)) {
        return {std::nullopt, "the reference's layer '" + layer + "' is black over the compared pixels"};
    }
    return {rel_mse(test_view, reference_view, pixels), ""};
}

ReferenceErrors::ReferenceErrors(ImageRGBA32F reference, int downsample_factor)
    : reference_(std::move(reference)),
      factor_(downsample_factor),
      reference_downsampled_(box_downsample(reference_, factor_)),
      range_(flip_exposure_range(rgb_view(reference_))),
      range_downsampled_(flip_exposure_range(rgb_view(reference_downsampled_))) {}

FrameErrors ReferenceErrors::measure(const ImageRGBA32F& test) const {
    FrameErrors errors;
    errors.full = compare_images(test, reference_, nullptr, &range_);
    errors.downsampled =
        compare_images(box_downsample(test, factor_), reference_downsampled_, nullptr, &range_downsampled_);
    errors.caustic = layer_rel_mse(test, reference_, kCausticLayer);
    errors.inscatter = layer_rel_mse(test, reference_, kInScatterLayer);
    return errors;
}

}  // namespace vkw::metrics
