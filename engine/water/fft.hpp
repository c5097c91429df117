// A plain radix-2 complex FFT in double precision: the CPU side of the FFT ocean, written
// for clarity and accuracy (twiddles from exact angles, no recurrences), not for speed.
#pragma once

#include <complex>
#include <cstdint>
#include <vector>

namespace vkw {

// In-place unnormalised inverse 2D DFT of an n x n array stored row-major
// (data[row * n + column]):
//   out[r][c] = sum over (b, a) of in[b][a] exp(+2 pi i (a c + b r) / n),
// with no 1/n^2 factor (the FFT ocean's mode amplitudes are per mode, Tessendorf 2001).
// n must be a power of two and data.size() == n * n; otherwise vkw::InternalError.
void fft_inverse_2d(std::vector<std::complex<double>>& data, uint32_t n);

}  // namespace vkw
