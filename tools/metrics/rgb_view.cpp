// Views, pixel selection and the shared input checks of the metrics.
#include "tools/metrics/rgb_view.hpp"

#include <cmath>

#include "engine/core/errors.hpp"
#include "tools/metrics/compensated_sum.hpp"

namespace vkw::metrics {
namespace {

void require_finite(const RgbView& view, const char* which) {
    std::size_t bad = 0;
    std::size_t first = 0;
    for (std::size_t p = 0; p < view.pixel_count(); ++p) {
        for (int c = 0; c < 3; ++c) {
            if (!std::isfinite(view.channel(p, c))) {
                if (bad == 0) first = p;
                ++bad;
            }
        }
    }
    if (bad > 0) {
        const std::size_t w = static_cast<std::size_t>(view.width);
        throw UserError(std::string("the ") + which + " image has " + std::to_string(bad) +
                        " non-finite RGB value(s), the first at pixel (" + std::to_string(first % w) + ", " +
                        std::to_string(first / w) + "); the metrics need finite values");
    }
}

}  // namespace

std::string size_text(int width, int height) { return std::to_string(width) + "x" + std::to_string(height); }

RgbView rgb_view(const ImageRGBA32F& image) {
    require_consistent_image(image);
    return RgbView{image.width, image.height, image.rgba.data(), 4};
}

RgbView layer_view(const ImageRGBA32F& image, const std::string& layer, const std::string& image_name) {
    require_consistent_image(image);
    std::string names;
    for (const ExtraLayer& extra : image.layers) {
        if (extra.name == layer) return RgbView{image.width, image.height, extra.rgb.data(), 3};
        names += (names.empty() ? "" : ", ") + extra.name;
    }
    throw UserError(image_name + " has no layer '" + layer + "' (its layers: " + (names.empty() ? "none" : names) +
                    ")");
}

std::vector<std::size_t> counted_pixels(int width, int height, const ImageRGBA32F* mask) {
    const std::size_t count = static_cast<std::size_t>(width) * static_cast<std::size_t>(height);
    std::vector<std::size_t> pixels;
    if (mask == nullptr) {
        pixels.resize(count);
        for (std::size_t p = 0; p < count; ++p) pixels[p] = p;
        return pixels;
    }
    require_consistent_image(*mask);
    if (mask->width != width || mask->height != height) {
        throw UserError("the mask is " + size_text(mask->width, mask->height) + " but the images are " +
                        size_text(width, height));
    }
    for (std::size_t p = 0; p < count; ++p) {
        if (mask->rgba[p * 4] > 0.5f) pixels.push_back(p);
    }
    if (pixels.empty()) throw UserError("the mask selects no pixel (none has R > 0.5)");
    return pixels;
}

void require_comparable(const RgbView& test, const RgbView& reference) {
    if (test.width != reference.width || test.height != reference.height) {
        throw UserError("the test image is " + size_text(test.width, test.height) + " but the reference is " +
                        size_text(reference.width, reference.height));
    }
    if (reference.pixel_count() == 0) throw UserError("the images are empty");
    require_finite(test, "test");
    require_finite(reference, "reference");
}

void require_comparable(const RgbView& test, const RgbView& reference, std::span<const std::size_t> pixels) {
    require_comparable(test, reference);
    if (pixels.empty()) throw UserError("no pixel is selected for comparison");
    for (std::size_t p : pixels) {
        if (p >= reference.pixel_count()) {
            throw InternalError("pixel index " + std::to_string(p) + " outside a " +
                                size_text(reference.width, reference.height) + " image");
        }
    }
}

double mean_rgb(const RgbView& view, std::span<const std::size_t> pixels) {
    CompensatedSum sum;
    for (std::size_t p : pixels) {
        for (int c = 0; c < 3; ++c) sum.add(view.channel(p, c));
    }
    return sum.value() / (3.0 * static_cast<double>(pixels.size()));
}

}  // namespace vkw::metrics
