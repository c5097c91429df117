// SplitMix64 over counters, and Box-Muller (counter_rng.hpp).
#include "engine/water/counter_rng.hpp"

#include <cmath>
#include <numbers>

namespace vkw {

uint64_t splitmix64(uint64_t x) {
    uint64_t z = x + 0x9e3779b97f4a7c15ULL;
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
    return z ^ (z >> 31);
}

uint64_t counter_bits(uint64_t seed, int64_t i, int64_t j, uint64_t stream) {
    // Each word is mixed in after the previous ones, so (i, j) and (j, i) differ.
    uint64_t h = splitmix64(seed);
    h = splitmix64(h ^ static_cast<uint64_t>(i));
    h = splitmix64(h ^ static_cast<uint64_t>(j));
    return splitmix64(h ^ stream);
}

double unit_interval_open_closed(uint64_t bits) { return double((bits >> 11) + 1) * 0x1.0p-53; }

std::array<double, 2> gaussian_pair(uint64_t seed, int64_t i, int64_t j) {
    const double u1 = unit_interval_open_closed(counter_bits(seed, i, j, 0));
    const double u2 = unit_interval_open_closed(counter_bits(seed, i, j, 1));
    const double radius = std::sqrt(-2.0 * std::log(u1));
    const double angle = 2.0 * std::numbers::pi * u2;
    return {radius * std::cos(angle), radius * std::sin(angle)};
}

}  // namespace vkw
