#include "tools/reference/pixel_footprint.hpp"

#include "engine/core/parallel.hpp"
#include "tools/reference/reference_renderer.hpp"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <optional>

namespace vkw::ref {

double PixelFootprints::quantile(double q) const {
    if (widths.empty()) return 0.0;
    const auto at = static_cast<size_t>(std::clamp(q, 0.0, 1.0) * double(widths.size() - 1) + 0.5);
    return widths[at];
}

double PixelFootprints::fraction_at_least(double width) const {
    if (widths.empty()) return 0.0;
    const auto below = std::lower_bound(widths.begin(), widths.end(), width) - widths.begin();
    return 1.0 - double(below) / double(widths.size());
}

PixelFootprints under_water_pixel_footprints(const Scene& scene, const WaterTransport& geometry, uint32_t width,
                                             uint32_t height, unsigned threads) {
    // The receiver point under the water that each pixel centre's view ray reaches, if any.
    std::vector<std::optional<glm::dvec3>> seen(size_t{width} * height);
    std::atomic<uint32_t> next_row{0};
    auto trace_rows = [&] {
        for (uint32_t y = next_row++; y < height; y = next_row++) {
            for (uint32_t x = 0; x < width; ++x) {
                seen[size_t{y} * width + x] =
                    geometry.trace_camera_ray(camera_ray(scene.camera, width, height, x + 0.5, y + 0.5)).caustic_point;
            }
        }
    };
    run_on_threads(threads ? threads : hardware_threads(), [&](unsigned) { trace_rows(); });

    PixelFootprints footprints;
    for (uint32_t y = 0; y + 1 < height; ++y) {
        for (uint32_t x = 0; x + 1 < width; ++x) {
            const auto& centre = seen[size_t{y} * width + x];
            const auto& right = seen[size_t{y} * width + x + 1];
            const auto& below = seen[size_t{y + 1} * width + x];
            if (!centre || !right || !below) continue;
            const glm::dvec3 a = *right - *centre, b = *below - *centre;
            const double la = glm::length(a), lb = glm::length(b);
            const double area = glm::length(glm::cross(a, b));
            footprints.widths.push_back(std::min({la, lb, area / std::max({la, lb, 1e-300})}));
        }
    }
    std::sort(footprints.widths.begin(), footprints.widths.end());
    return footprints;
}

}  // namespace vkw::ref
