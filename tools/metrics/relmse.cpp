// relMSE with the worst 0.1% of the per-value terms dropped (definition in metrics.hpp).
#include <algorithm>
#include <vector>

#include "engine/core/errors.hpp"
#include "tools/metrics/compensated_sum.hpp"
#include "tools/metrics/metrics.hpp"

namespace vkw::metrics {

double rel_mse(const RgbView& test, const RgbView& reference, std::span<const std::size_t> pixels) {
    require_comparable(test, reference, pixels);
    const double s = mean_rgb(reference, pixels);
    if (!(s > 0.0)) {
        throw UserError("relMSE needs a reference with a positive mean over the compared pixels (it is " +
                        std::to_string(s) + ")");
    }
    std::vector<double> terms;
    terms.reserve(pixels.size() * 3);
    for (std::size_t p : pixels) {
        for (int c = 0; c < 3; ++c) {
            const double a = test.channel(p, c) / s;
            const double b = reference.channel(p, c) / s;
            terms.push_back((a - b) * (a - b) / (b * b + kRelMseEpsilon));
        }
    }
    const std::size_t n = terms.size();
    const std::size_t dropped = n / 1000;  // floor(0.001 n), in integers so 1000 values drop exactly 1
    const std::size_t kept = n - dropped;
    // Afterwards the first `kept` terms are the smallest ones (in no particular order).
    std::nth_element(terms.begin(), terms.begin() + static_cast<std::ptrdiff_t>(kept), terms.end());
    CompensatedSum sum;
    for (std::size_t i = 0; i < kept; ++i) sum.add(terms[i]);
    return sum.value() / static_cast<double>(kept);
}

}  // namespace vkw::metrics
