// Shape checks for ImageRGBA32F, shared by every writer so each one can trust the sizes.
#include "engine/image/image.hpp"

#include <algorithm>
#include <cmath>
#include <set>

#include "engine/core/errors.hpp"

namespace vkw {

void require_consistent_image(const ImageRGBA32F& image) {
    auto fail = [](const std::string& why) { throw InternalError("inconsistent image: " + why); };

    if (image.width <= 0 || image.height <= 0) {
        fail("size " + std::to_string(image.width) + "x" + std::to_string(image.height) + " is empty");
    }
    const std::size_t pixels = image.pixel_count();
    if (image.rgba.size() != pixels * 4) {
        fail("rgba holds " + std::to_string(image.rgba.size()) + " floats, expected " + std::to_string(pixels * 4));
    }
    std::set<std::string> names;
    for (const ExtraLayer& layer : image.layers) {
        if (layer.name.empty()) fail("an extra layer has an empty name");
        if (!names.insert(layer.name).second) fail("extra layer '" + layer.name + "' appears twice");
        if (layer.rgb.size() != pixels * 3) {
            fail("layer '" + layer.name + "' holds " + std::to_string(layer.rgb.size()) + " floats, expected " +
                 std::to_string(pixels * 3));
        }
    }
}

std::size_t count_nonfinite_values(const ImageRGBA32F& image) {
    auto count = [](const std::vector<float>& values) {
        return static_cast<std::size_t>(
            std::count_if(values.begin(), values.end(), [](float v) { return !std::isfinite(v); }));
    };
    std::size_t total = count(image.rgba);
    for (const ExtraLayer& layer : image.layers) total += count(layer.rgb);
    return total;
}

void require_finite_image(const ImageRGBA32F& image, const std::string& what) {
    const std::size_t bad = count_nonfinite_values(image);
    if (bad == 0) return;
    throw UserError(what + " has " + std::to_string(bad) +
                    " non-finite values (NaN or infinity), so nothing was written: a scene value probably overflows "
                    "32-bit floats (radiance, irradiance, an amplitude or a size; scenes/README.md gives the limits)");
}

}  // namespace vkw
