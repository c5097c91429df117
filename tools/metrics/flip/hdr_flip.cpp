// HDR-FLIP: LDR-FLIP of both images at each exposure of the range, each pixel's maximum.
#include "tools/metrics/flip/hdr_flip.hpp"

#include <algorithm>
#include <cmath>
#include <future>
#include <string>
#include <thread>

#include "engine/core/errors.hpp"
#include "tools/metrics/compensated_sum.hpp"
#include "tools/metrics/flip/ldr_flip.hpp"

namespace vkw::metrics {
namespace {

// The image's RGB times `scale` through `map`, as three planes.
template <typename Map>
flip::Planes3 to_planes(const RgbView& view, double scale, Map map) {
    flip::Planes3 planes = flip::make_planes3(view.width, view.height);
    for (std::size_t p = 0; p < view.pixel_count(); ++p) {
        for (int c = 0; c < 3; ++c) planes[c][p] = static_cast<float>(map(view.channel(p, c) * scale));
    }
    return planes;
}

}  // namespace

std::vector<float> hdr_flip_map(const RgbView& test, const RgbView& reference, const FlipExposureRange& range) {
    require_comparable(test, reference);
    if (range.count < 1 || !std::isfinite(range.start) || !std::isfinite(range.stop)) {
        throw InternalError("invalid HDR-FLIP exposure range: start " + std::to_string(range.start) + ", stop " +
                            std::to_string(range.stop) + ", " + std::to_string(range.count) + " exposure(s)");
    }
    const flip::LdrFlipFilters filters = flip::ldr_flip_filters(kFlipPixelsPerDegree);
    // The exposures are independent: a few workers take every workers-th one and keep their own
    // per-pixel maximum. The maximum does not depend on the order, so the result is the same
    // as one thread's. At most 4 workers: each holds about 160 bytes per pixel while it works.
    const int workers = std::clamp(static_cast<int>(std::thread::hardware_concurrency()), 1, std::min(4, range.count));
    auto work = [&](int first) {
        std::vector<float> worst(reference.pixel_count(), 0.0f);
        for (int i = first; i < range.count; i += workers) {
            const double scale = std::exp2(range.exposure(i));
            const flip::PreparedImage t = flip::prepare(to_planes(test, scale, hdr_flip_tone_map), filters);
            const flip::PreparedImage r = flip::prepare(to_planes(reference, scale, hdr_flip_tone_map), filters);
            const flip::Plane error = flip::ldr_flip(t, r);
            for (std::size_t p = 0; p < worst.size(); ++p) worst[p] = std::max(worst[p], error[p]);
        }
        return worst;
    };
    std::vector<std::future<std::vector<float>>> others;
    for (int first = 1; first < workers; ++first) others.push_back(std::async(std::launch::async, work, first));
    std::vector<float> result = work(0);
    for (auto& other : others) {
        const std::vector<float> worst = other.get();  // rethrows a worker's exception
        for (std::size_t p = 0; p < result.size(); ++p) result[p] = std::max(result[p], worst[p]);
    }
    return result;
}

std::vector<float> ldr_flip_map(const RgbView& test, const RgbView& reference) {
    require_comparable(test, reference);
    const flip::LdrFlipFilters filters = flip::ldr_flip_filters(kFlipPixelsPerDegree);
    auto clamp01 = [](double v) { return std::clamp(v, 0.0, 1.0); };
    const flip::PreparedImage t = flip::prepare(to_planes(test, 1.0, clamp01), filters);
    const flip::PreparedImage r = flip::prepare(to_planes(reference, 1.0, clamp01), filters);
    return flip::ldr_flip(t, r).values;
}

double flip_mean(const RgbView& test, const RgbView& reference, std::span<const std::size_t> pixels,
                 const FlipExposureRange& range) {
    require_comparable(test, reference, pixels);
    const std::vector<float> map = hdr_flip_map(test, reference, range);
    CompensatedSum sum;
    for (std::size_t p : pixels) sum.add(map[p]);
    return sum.value() / static_cast<double>(pixels.size());
}

}  // namespace vkw::metrics
