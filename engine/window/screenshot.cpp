#include "engine/window/screenshot.hpp"

#include "engine/image/exr_io.hpp"
#include "engine/image/png_preview.hpp"

#include <cstring>
#include <utility>

namespace vkw::window {

std::filesystem::path write_screenshot(const std::filesystem::path& exr, const float* rgba, uint32_t width,
                                       uint32_t height, float exposure, std::vector<ImageAttribute> attributes) {
    ImageRGBA32F image;
    image.width = static_cast<int>(width);
    image.height = static_cast<int>(height);
    image.rgba.resize(size_t{width} * height * 4);
    std::memcpy(image.rgba.data(), rgba, image.rgba.size() * sizeof(float));
    image.attributes = std::move(attributes);
    write_exr(exr, image, ExrPixelType::Float);
    const std::filesystem::path png = std::filesystem::path(exr).replace_extension(".png");
    write_png_preview(png, image, exposure);
    return png;
}

}  // namespace vkw::window
