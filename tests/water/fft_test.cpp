// The radix-2 inverse FFT against the O(n^4) definition of the inverse 2D DFT.
#include <cmath>
#include <complex>
#include <cstdint>
#include <limits>
#include <numbers>
#include <vector>

#include <gtest/gtest.h>

#include "engine/core/errors.hpp"
#include "engine/water/counter_rng.hpp"
#include "engine/water/fft.hpp"

namespace vkw {
namespace {

std::vector<std::complex<double>> random_array(uint32_t n, uint64_t seed) {
    std::vector<std::complex<double>> data(std::size_t(n) * n);
    for (uint32_t i = 0; i < data.size(); ++i) {
        const auto g = gaussian_pair(seed, i, 0);
        data[i] = {g[0], g[1]};
    }
    return data;
}

// out[r][c] = sum over (b, a) of in[b][a] exp(+2 pi i (a c + b r) / n), the exponent reduced
// modulo n so that every twiddle comes from an angle in [0, 2 pi).
std::vector<std::complex<double>> naive_inverse_dft(const std::vector<std::complex<double>>& in, uint32_t n) {
    std::vector<std::complex<double>> out(in.size());
    for (uint32_t r = 0; r < n; ++r) {
        for (uint32_t c = 0; c < n; ++c) {
            std::complex<double> sum = 0.0;
            for (uint32_t b = 0; b < n; ++b) {
                for (uint32_t a = 0; a < n; ++a) {
                    const uint32_t turns = (a * c + b * r) % n;
                    sum += in[b * n + a] * std::polar(1.0, 2.0 * std::numbers::pi * turns / n);
                }
            }
            out[r * n + c] = sum;
        }
    }
    return out;
}

TEST(water_fft, MatchesTheNaiveDftOn16x16) {
    const uint32_t n = 16;
    const auto input = random_array(n, 7);
    auto fast = input;
    fft_inverse_2d(fast, n);
    const auto slow = naive_inverse_dft(input, n);
    // Every output is a sum of n^2 terms bounded by sum|in|; each rounding step errs by at
    // most eps times a partial sum, so n^2 eps sum|in| bounds the error of either method.
    double sum_abs = 0.0;
    for (const auto& v : input) sum_abs += std::abs(v);
    const double tolerance = double(n) * n * std::numeric_limits<double>::epsilon() * sum_abs;
    for (std::size_t i = 0; i < fast.size(); ++i) {
        EXPECT_NEAR(fast[i].real(), slow[i].real(), tolerance) << "index " << i;
        EXPECT_NEAR(fast[i].imag(), slow[i].imag(), tolerance) << "index " << i;
    }
}

TEST(water_fft, OneModeGivesOnePlaneWave) {
    const uint32_t n = 32;
    std::vector<std::complex<double>> data(n * n, 0.0);
    data[3 * n + 5] = 1.0;  // fz = 3, fx = 5
    fft_inverse_2d(data, n);
    for (uint32_t r = 0; r < n; ++r) {
        for (uint32_t c = 0; c < n; ++c) {
            const auto expected = std::polar(1.0, 2.0 * std::numbers::pi * ((5 * c + 3 * r) % n) / n);
            // A single term: only the butterflies' rounding, a few eps per pass (log2 n^2 = 10).
            EXPECT_NEAR(std::abs(data[r * n + c] - expected), 0.0, 1e-14);
        }
    }
}

TEST(water_fft, SizeOneIsTheIdentity) {
    std::vector<std::complex<double>> data{{2.5, -1.0}};
    fft_inverse_2d(data, 1);
    EXPECT_EQ(data[0], std::complex<double>(2.5, -1.0));
}

TEST(water_fft, RefusesNonPowersOfTwoAndWrongSizes) {
    std::vector<std::complex<double>> data(12 * 12);
    EXPECT_THROW(fft_inverse_2d(data, 12), InternalError);
    std::vector<std::complex<double>> short_data(15);
    EXPECT_THROW(fft_inverse_2d(short_data, 4), InternalError);
}

}  // namespace
}  // namespace vkw
