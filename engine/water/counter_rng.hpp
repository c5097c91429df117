// A counter-based random generator: the random numbers of a spectrum mode are a pure
// function of (seed, frequency indices), not of the order in which modes are visited.
// So the same seed gives the same ocean on any machine and at any grid resolution (a mode
// keeps its numbers when the resolution grows), and the GPU can be handed the very same h0.
//
// Integer part: the SplitMix64 output function (Steele, Lea and Flood, "Fast splittable
// pseudorandom number generators", OOPSLA 2014) chained over the counter words; exact
// integer arithmetic, so bit-identical everywhere. Gaussians by Box-Muller, whose log, cos
// and sin come from the C library: identical wherever the same libm is used (glibc on
// every vkwater platform), possibly 1 ulp apart elsewhere.
#pragma once

#include <array>
#include <cstdint>

namespace vkw {

// SplitMix64's step: adds the golden-ratio increment, then mixes (a bijection on 64 bits).
uint64_t splitmix64(uint64_t x);

// 64 random bits for the counter (seed, i, j, stream).
uint64_t counter_bits(uint64_t seed, int64_t i, int64_t j, uint64_t stream);

// A double uniform in (0, 1] from the top 53 bits (never 0, so log() is finite).
double unit_interval_open_closed(uint64_t bits);

// Two independent standard normal deviates for the counter (seed, i, j).
std::array<double, 2> gaussian_pair(uint64_t seed, int64_t i, int64_t j);

}  // namespace vkw
