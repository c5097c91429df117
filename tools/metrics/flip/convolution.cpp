// Clamped-edge 1D correlation along rows or columns.
#include "tools/metrics/flip/convolution.hpp"

#include <algorithm>
#include <vector>

#include "engine/core/errors.hpp"

namespace vkw::metrics::flip {
namespace {

Plane correlate_x(const Plane& in, std::span<const double> kernel, int r) {
    // Each row is copied with r clamped pixels added at both ends; then one tap at a time over
    // the whole row (the same order as correlate_y, and a loop the compiler vectorises).
    Plane out(in.width, in.height);
    const std::size_t w = static_cast<std::size_t>(in.width);
    std::vector<double> padded(w + 2 * static_cast<std::size_t>(r));
    std::vector<double> sum(w);
    for (int y = 0; y < in.height; ++y) {
        const float* row = in.values.data() + static_cast<std::size_t>(y) * w;
        for (std::size_t j = 0; j < padded.size(); ++j) {
            const long x = static_cast<long>(j) - r;
            padded[j] = row[std::clamp(x, 0L, static_cast<long>(w) - 1)];
        }
        std::fill(sum.begin(), sum.end(), 0.0);
        for (int i = 0; i <= 2 * r; ++i) {
            const double k = kernel[i];
            const double* shifted = padded.data() + i;  // padded[x + i] = in(clamp(x + i - r))
            for (std::size_t x = 0; x < w; ++x) sum[x] += k * shifted[x];
        }
        float* out_row = out.values.data() + static_cast<std::size_t>(y) * w;
        for (std::size_t x = 0; x < w; ++x) out_row[x] = static_cast<float>(sum[x]);
    }
    return out;
}

Plane correlate_y(const Plane& in, std::span<const double> kernel, int r) {
    // Whole rows at a time: out row y = sum_i kernel[i + r] * in row clamp(y + i).
    Plane out(in.width, in.height);
    const std::size_t w = static_cast<std::size_t>(in.width);
    std::vector<double> sum(w);
    for (int y = 0; y < in.height; ++y) {
        std::fill(sum.begin(), sum.end(), 0.0);
        for (int i = -r; i <= r; ++i) {
            const double k = kernel[i + r];
            const float* row = in.values.data() + static_cast<std::size_t>(std::clamp(y + i, 0, in.height - 1)) * w;
            for (std::size_t x = 0; x < w; ++x) sum[x] += k * row[x];
        }
        float* out_row = out.values.data() + static_cast<std::size_t>(y) * w;
        for (std::size_t x = 0; x < w; ++x) out_row[x] = static_cast<float>(sum[x]);
    }
    return out;
}

}  // namespace

Plane correlate(const Plane& in, std::span<const double> kernel, Axis axis) {
    if (kernel.size() % 2 != 1) throw InternalError("FLIP filter kernels have an odd number of taps");
    const int r = static_cast<int>(kernel.size() / 2);
    return axis == Axis::X ? correlate_x(in, kernel, r) : correlate_y(in, kernel, r);
}

Plane correlate_separable(const Plane& in, std::span<const double> kernel_x, std::span<const double> kernel_y) {
    return correlate(correlate(in, kernel_x, Axis::X), kernel_y, Axis::Y);
}

}  // namespace vkw::metrics::flip
