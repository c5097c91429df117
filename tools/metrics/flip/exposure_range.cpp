// HDR-FLIP's tone mapper and the exposure range it derives from the reference image.
#include <algorithm>
#include <cmath>
#include <vector>

#include "engine/core/errors.hpp"
#include "tools/metrics/colour.hpp"
#include "tools/metrics/flip/hdr_flip.hpp"

namespace vkw::metrics {
namespace {

// The rational tone curve (k0 x^2 + k1 x + k2) / (k3 x^2 + k4 x + k5): ACES (Narkowicz) with
// the 0.6 pre-exposure folded in. k2 = 0.
constexpr double kK0 = 0.6 * 0.6 * 2.51, kK1 = 0.6 * 0.03, kK3 = 0.6 * 0.6 * 2.43, kK4 = 0.6 * 0.59, kK5 = 0.14;

// The tone-mapped value that the brightest and the median reference pixel are exposed to.
constexpr double kTargetValue = 0.85;

double median(std::vector<double> values) {
    const std::size_t n = values.size();
    const auto middle = values.begin() + static_cast<std::ptrdiff_t>(n / 2);
    std::nth_element(values.begin(), middle, values.end());
    if (n % 2 == 1) return *middle;
    const double upper = *middle;
    const double lower = *std::max_element(values.begin(), middle);  // the largest of the lower half
    return 0.5 * (lower + upper);
}

}  // namespace

double hdr_flip_tone_map(double x) {
    if (!(x > 0.0)) return 0.0;
    // The curve passes 1 near x = 12.1 and stays above it; stopping early keeps x^2 finite.
    if (x > 1.0e4) return 1.0;
    return std::clamp((kK0 * x * x + kK1 * x) / (kK3 * x * x + kK4 * x + kK5), 0.0, 1.0);
}

double hdr_flip_inverse_tone_map(double t) {
    // (k0 - t k3) x^2 + (k1 - t k4) x - t k5 = 0; for 0 < t < 1 the leading coefficient is
    // positive and the constant negative, so exactly one root is positive.
    const double a = kK0 - t * kK3, b = kK1 - t * kK4, c = -t * kK5;
    return (-b + std::sqrt(b * b - 4.0 * a * c)) / (2.0 * a);
}

FlipExposureRange flip_exposure_range(const RgbView& reference) {
    std::vector<double> luminances;
    luminances.reserve(reference.pixel_count());
    for (std::size_t p = 0; p < reference.pixel_count(); ++p) {
        Vec3 rgb{};
        for (int c = 0; c < 3; ++c) rgb[c] = std::max(reference.channel(p, c), 0.0);
        const double y = luminance(rgb);
        if (!std::isfinite(y)) throw UserError("the reference image has non-finite values");
        luminances.push_back(y);
    }
    if (luminances.empty()) throw UserError("the reference image is empty");
    const double y_max = *std::max_element(luminances.begin(), luminances.end());
    if (!(y_max > 0.0)) return FlipExposureRange{};
    double y_median = median(luminances);
    if (!(y_median > 0.0)) {
        std::erase_if(luminances, [](double y) { return !(y > 0.0); });
        y_median = median(std::move(luminances));
    }
    const double x = hdr_flip_inverse_tone_map(kTargetValue);
    FlipExposureRange range;
    range.start = std::log2(x / y_max);
    range.stop = std::log2(x / y_median);
    range.count = range.start == range.stop ? 1 : static_cast<int>(std::max(2.0, std::ceil(range.stop - range.start)));
    return range;
}

FlipExposureRange flip_exposure_range(const ImageRGBA32F& reference) {
    return flip_exposure_range(rgb_view(reference));
}

}  // namespace vkw::metrics
