// Mean CIE L*u*v* distance at a middle-grey exposure (definition in metrics.hpp).
#include <algorithm>
#include <cmath>

#include "engine/core/errors.hpp"
#include "tools/metrics/colour.hpp"
#include "tools/metrics/compensated_sum.hpp"
#include "tools/metrics/metrics.hpp"

namespace vkw::metrics {
namespace {

constexpr double kMiddleGrey = 0.18;

Vec3 exposed_luv(const RgbView& view, std::size_t p, double exposure) {
    Vec3 rgb{};
    for (int c = 0; c < 3; ++c) rgb[c] = std::clamp(view.channel(p, c) * exposure, 0.0, 1.0);
    return xyz_to_luv(linear_srgb_to_xyz(rgb));
}

}  // namespace

double luv_mean_distance(const RgbView& test, const RgbView& reference, std::span<const std::size_t> pixels) {
    require_comparable(test, reference, pixels);
    CompensatedSum reference_luminance;
    for (std::size_t p : pixels) {
        reference_luminance.add(luminance({reference.channel(p, 0), reference.channel(p, 1), reference.channel(p, 2)}));
    }
    const double mean_luminance = reference_luminance.value() / static_cast<double>(pixels.size());
    if (!(mean_luminance > 0.0)) {
        throw UserError(
            "the L*u*v* distance needs a reference with a positive mean luminance over the compared "
            "pixels (it is " +
            std::to_string(mean_luminance) + ")");
    }
    const double exposure = kMiddleGrey / mean_luminance;
    CompensatedSum distance;
    for (std::size_t p : pixels) {
        const Vec3 a = exposed_luv(test, p, exposure);
        const Vec3 b = exposed_luv(reference, p, exposure);
        distance.add(
            std::sqrt((a[0] - b[0]) * (a[0] - b[0]) + (a[1] - b[1]) * (a[1] - b[1]) + (a[2] - b[2]) * (a[2] - b[2])));
    }
    return distance.value() / static_cast<double>(pixels.size());
}

}  // namespace vkw::metrics
