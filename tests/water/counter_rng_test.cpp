// The counter-based generator behind the FFT ocean's h0: fixed known values, independence of
// the counter order, and the first two moments of its gaussians.
#include <cmath>
#include <cstdint>

#include <gtest/gtest.h>

#include "engine/water/counter_rng.hpp"

namespace vkw {
namespace {

TEST(water_counter_rng, SplitMix64MatchesTheReferenceSequence) {
    // The first two outputs of the reference SplitMix64 generator seeded with 0
    // (its state advances by the golden-ratio increment before each mix).
    EXPECT_EQ(splitmix64(0), 0xe220a8397b1dcdafULL);
    EXPECT_EQ(splitmix64(0x9e3779b97f4a7c15ULL), 0x6e789e6aa1b965f4ULL);
}

TEST(water_counter_rng, DependsOnEveryCounterWordAndItsOrder) {
    const uint64_t base = counter_bits(1, 2, 3, 0);
    EXPECT_EQ(base, counter_bits(1, 2, 3, 0));
    EXPECT_NE(base, counter_bits(2, 2, 3, 0));
    EXPECT_NE(base, counter_bits(1, 3, 2, 0));
    EXPECT_NE(base, counter_bits(1, -2, 3, 0));
    EXPECT_NE(base, counter_bits(1, 2, 3, 1));
}

TEST(water_counter_rng, UniformsAreInTheHalfOpenInterval) {
    EXPECT_EQ(unit_interval_open_closed(0), 0x1.0p-53);
    EXPECT_EQ(unit_interval_open_closed(~0ULL), 1.0);
}

TEST(water_counter_rng, GaussiansHaveZeroMeanAndUnitVariance) {
    const int count = 200000;  // 100000 pairs
    double sum = 0.0, sum_sq = 0.0;
    for (int i = 0; i < count / 2; ++i) {
        const auto g = gaussian_pair(42, i, -i);
        sum += g[0] + g[1];
        sum_sq += g[0] * g[0] + g[1] * g[1];
    }
    const double mean = sum / count;
    const double variance = sum_sq / count - mean * mean;
    // Standard errors: 1 / sqrt(count) for the mean, sqrt(2 / count) for the variance
    // (a normal's fourth moment is 3). Five standard errors.
    EXPECT_NEAR(mean, 0.0, 5.0 / std::sqrt(count));
    EXPECT_NEAR(variance, 1.0, 5.0 * std::sqrt(2.0 / count));
}

}  // namespace
}  // namespace vkw
