// The in-memory linear HDR image that the renderer hands to the EXR and PNG writers
// (and that read_exr returns).
#pragma once

#include <cassert>
#include <cstddef>
#include <string>
#include <vector>

namespace vkw {

// An additional named RGB image of the same size as the main one (e.g. the caustic
// contribution alone); EXR stores it as the channels "<name>.R", "<name>.G", "<name>.B".
struct ExtraLayer {
    std::string name;        // e.g. "caustic"
    std::vector<float> rgb;  // 3 floats per pixel, same pixel order as ImageRGBA32F::rgba
};

// A named text that travels with the image: what made it (EXR stores each as a string attribute
// of the header; the pixels never depend on them).
struct ImageAttribute {
    std::string name;  // e.g. "software", "vkwater/scene"
    std::string value;
};

struct ImageRGBA32F {
    int width = 0;
    int height = 0;
    std::vector<float> rgba;  // 4 floats per pixel, row-major, row 0 is the TOP row of the picture
    std::vector<ExtraLayer> layers;
    std::vector<ImageAttribute> attributes;

    std::size_t pixel_count() const { return static_cast<std::size_t>(width) * static_cast<std::size_t>(height); }

    float* pixel(int x, int y) { return rgba.data() + offset(x, y); }
    const float* pixel(int x, int y) const { return rgba.data() + offset(x, y); }

private:
    std::size_t offset(int x, int y) const {
        assert(x >= 0 && x < width && y >= 0 && y < height);
        return (static_cast<std::size_t>(y) * static_cast<std::size_t>(width) + static_cast<std::size_t>(x)) * 4;
    }
};

// Throws InternalError unless the sizes agree (width, height > 0, rgba and every layer's rgb
// hold one value per channel per pixel, layer names non-empty and unique). A malformed
// in-memory image is a bug in the caller, not something the user can fix, hence not UserError.
void require_consistent_image(const ImageRGBA32F& image);

// The NaN and infinite values in the image's RGBA and its layers.
std::size_t count_nonfinite_values(const ImageRGBA32F& image);

// Throws UserError naming `what` (the image's origin) when the image holds a NaN or an infinity:
// a command never writes one and exits 0. Scene values beyond what 32-bit floats hold (radiance,
// irradiance, amplitudes, sizes) are the usual cause, hence a user error.
void require_finite_image(const ImageRGBA32F& image, const std::string& what);

}  // namespace vkw
