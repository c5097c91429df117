// The 2-thread C++ scatter (cpu_scatter.hpp).
#include "tools/benchmarks/cpu_scatter.hpp"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cstring>
#include <thread>
#include <vector>

namespace vkwbench {
namespace {

constexpr int kThreads = 2;
constexpr uint64_t kPhotonUnits = 1u << 20;  // as caustic_scatter_fixed.comp

// The four taps of a photon at a quarter texel from its texel's centre, split as the shader
// splits them (round(q w), the rest to the other tap), so the CPU adds the same integers.
struct Taps {
    uint64_t x0y0, x0y1, x1y0, x1y1;
};
Taps photon_taps() {
    auto share = [](uint64_t q, float w) { return std::min<uint64_t>(uint64_t(float(q) * w + 0.5f), q); };
    const uint64_t x0 = share(kPhotonUnits, 0.75f), x1 = kPhotonUnits - x0;
    const uint64_t x0y0 = share(x0, 0.75f), x1y0 = share(x1, 0.75f);
    return {x0y0, x0 - x0y0, x1y0, x1 - x1y0};
}

// Photon rows [first, last) into `map` (three uint64 per texel), with `add` doing each addition.
template <class Add>
void scatter_rows(uint32_t first, uint32_t last, uint32_t resolution, uint32_t width, uint32_t margin_x,
                  uint32_t margin_y, const Taps& taps, Add add) {
    for (uint32_t j = first; j < last; ++j) {
        for (uint32_t i = 0; i < resolution; ++i) {
            const size_t t00 = (size_t(j + 1 + margin_y) * width + (i + 1 + margin_x)) * 3;
            const size_t t01 = t00 + size_t(width) * 3, t10 = t00 + 3, t11 = t01 + 3;
            for (size_t c = 0; c < 3; ++c) {
                add(t00 + c, taps.x0y0);
                add(t01 + c, taps.x0y1);
                add(t10 + c, taps.x1y0);
                add(t11 + c, taps.x1y1);
            }
        }
    }
}

}  // namespace

const char* cpu_scatter_name(CpuScatterMethod method) {
    return method == CpuScatterMethod::PrivateBuffers ? "2 threads, private maps + reduction"
                                                      : "2 threads, shared map, atomic fetch_add";
}

CpuScatterResult cpu_scatter(CpuScatterMethod method, const ScatterPush& push) {
    const uint32_t resolution = push.resolution, width = push.width, margin_x = push.margin_x, margin_y = push.margin_y;
    const size_t values = size_t(width) * push.height * 3;
    const Taps taps = photon_taps();
    // Zeroed maps before the clock starts (the GPU's scatter is timed without its clear pass).
    std::vector<uint64_t> result(values, 0);
    std::vector<uint64_t> second(method == CpuScatterMethod::PrivateBuffers ? values : 0, 0);
    const auto start = std::chrono::steady_clock::now();
    if (method == CpuScatterMethod::PrivateBuffers) {
        std::vector<uint64_t>* maps[kThreads] = {&result, &second};
        std::thread threads[kThreads];
        for (int t = 0; t < kThreads; ++t) {
            threads[t] = std::thread([&, t] {
                uint64_t* map = maps[t]->data();
                scatter_rows(resolution * t / kThreads, resolution * (t + 1) / kThreads, resolution, width, margin_x,
                             margin_y, taps, [map](size_t k, uint64_t q) { map[k] += q; });
            });
        }
        for (std::thread& thread : threads) thread.join();
        for (size_t k = 0; k < values; ++k) result[k] += second[k];
    } else {
        std::thread threads[kThreads];
        for (int t = 0; t < kThreads; ++t) {
            threads[t] = std::thread([&, t] {
                uint64_t* map = result.data();
                scatter_rows(resolution * t / kThreads, resolution * (t + 1) / kThreads, resolution, width, margin_x,
                             margin_y, taps, [map](size_t k, uint64_t q) {
                                 std::atomic_ref<uint64_t>(map[k]).fetch_add(q, std::memory_order_relaxed);
                             });
            });
        }
        for (std::thread& thread : threads) thread.join();
    }
    const double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    uint64_t checksum = 0;
    for (const uint64_t v : result) checksum += v;
    return {ms, checksum};
}

}  // namespace vkwbench
