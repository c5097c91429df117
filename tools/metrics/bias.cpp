// Signed mean bias mean(a) / mean(b) - 1: does the test carry the reference's energy?
#include "engine/core/errors.hpp"
#include "tools/metrics/metrics.hpp"

namespace vkw::metrics {

double mean_bias(const RgbView& test, const RgbView& reference, std::span<const std::size_t> pixels) {
    require_comparable(test, reference, pixels);
    const double b = mean_rgb(reference, pixels);
    if (!(b > 0.0)) {
        throw UserError("the bias needs a reference with a positive mean over the compared pixels (it is " +
                        std::to_string(b) + ")");
    }
    return mean_rgb(test, pixels) / b - 1.0;
}

}  // namespace vkw::metrics
