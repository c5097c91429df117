// Iterative radix-2 Cooley-Tukey (decimation in time): bit-reversal permutation, then
// log2(n) butterfly passes. The 2D transform is n row transforms then n column transforms.
#include "engine/water/fft.hpp"

#include <cstddef>
#include <numbers>
#include <string>
#include <utility>

#include "engine/core/errors.hpp"

namespace vkw {

namespace {

// exp(+2 pi i j / n) for j < n / 2, each from its own angle so that no rounding accumulates.
std::vector<std::complex<double>> twiddles(uint32_t n) {
    std::vector<std::complex<double>> table(n / 2);
    for (uint32_t j = 0; j < n / 2; ++j) {
        table[j] = std::polar(1.0, 2.0 * std::numbers::pi * double(j) / double(n));
    }
    return table;
}

// In-place inverse DFT of the contiguous sequence line[0..n).
void fft_inverse_1d(std::complex<double>* line, uint32_t n, const std::vector<std::complex<double>>& table) {
    for (uint32_t i = 1, j = 0; i < n; ++i) {
        uint32_t bit = n >> 1;
        for (; j & bit; bit >>= 1) {
            j ^= bit;
        }
        j |= bit;
        if (i < j) {
            std::swap(line[i], line[j]);
        }
    }
    for (uint32_t length = 2; length <= n; length <<= 1) {
        const uint32_t half = length / 2;
        const uint32_t stride = n / length;  // table index step: exp(2 pi i j / length)
        for (uint32_t start = 0; start < n; start += length) {
            for (uint32_t j = 0; j < half; ++j) {
                const std::complex<double> odd = line[start + j + half] * table[j * stride];
                const std::complex<double> even = line[start + j];
                line[start + j] = even + odd;
                line[start + j + half] = even - odd;
            }
        }
    }
}

}  // namespace

void fft_inverse_2d(std::vector<std::complex<double>>& data, uint32_t n) {
    if (n == 0 || (n & (n - 1)) != 0 || data.size() != std::size_t(n) * n) {
        throw InternalError("fft_inverse_2d: n = " + std::to_string(n) +
                            " must be a power of two with data.size() = n * n (got " + std::to_string(data.size()) +
                            ")");
    }
    const std::vector<std::complex<double>> table = twiddles(n);
    for (uint32_t row = 0; row < n; ++row) {
        fft_inverse_1d(data.data() + std::size_t(row) * n, n, table);
    }
    std::vector<std::complex<double>> column(n);
    for (uint32_t c = 0; c < n; ++c) {
        for (uint32_t r = 0; r < n; ++r) {
            column[r] = data[std::size_t(r) * n + c];
        }
        fft_inverse_1d(column.data(), n, table);
        for (uint32_t r = 0; r < n; ++r) {
            data[std::size_t(r) * n + c] = column[r];
        }
    }
}

}  // namespace vkw
