// The FFT ocean evaluated on its n x n grid by inverse FFTs: the fast path (one FFT per
// field) for meshes and for comparing with the GPU, which runs the same transform. Between
// grid points use FftOceanSurface, which sums the same series exactly.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "engine/water/fft_ocean.hpp"

namespace vkw {

struct FftOceanGrid {
    uint32_t n = 0;
    double patch_size = 0.0;  // m
    double time = 0.0;        // s
    double choppiness = 0.0;
    // fields[f][iz * n + ix] is field f (OceanField) at the parameter
    // (x0, z0) = (ix, iz) * patch_size / n.
    std::array<std::vector<double>, kOceanFieldCount> fields;

    double spacing() const { return patch_size / n; }
    OceanFieldValues values(uint32_t ix, uint32_t iz) const;
    // The surface point at grid node (ix, iz) for a mean water level `level`.
    SurfacePoint point(uint32_t ix, uint32_t iz, double level) const;
    double max_abs_height() const;
};

// One inverse FFT per field of m_f(k) h~(k, t) (fft_ocean.hpp); the imaginary parts, zero
// but for rounding since every spectrum is Hermitian, are dropped.
FftOceanGrid evaluate_ocean_grid(const FftOceanSpectrum& spectrum, double choppiness, double time);

}  // namespace vkw
