// The FFT ocean, fast and with a bounded error, for the CPU reference renderer.
// FftOceanSurface sums all n^2 modes at every point (exact, about a millisecond per point at
// n = 256): far too slow for crossing view rays and for mapping millions of caustic beams.
//
// The series is periodic and band-limited, so an inverse FFT of its modes zero-padded to
// N = P n per axis gives its EXACT values (to rounding) on a P-times finer grid of spacing
// h = patch_size / N; spectral differentiation (multiplying mode k by i kx, i kz) gives the
// exact x, z and cross derivatives there too. Between the samples each field of
// fft_ocean.hpp (height, displacements, slopes, displacement derivatives) is a tensor-product
// cubic Hermite interpolant of its own exact value, d/dx0, d/dz0 and d2/dx0dz0. Its error is
// bounded from the spectrum (error_bound()):
//   1D cubic Hermite: |f - H f| <= h^4 / 384 max|f''''|   ((x-a)^2 (x-b)^2 <= h^4 / 16, / 4!);
//   tensor product:   f - Hx Hz f = (f - Hx f) + Hx (f - Hz f), and |Hx g| <= max|g| + h/4 max|g'|
//                     (the value basis is a partition of unity >= 0, the slope basis sums to
//                     t (1 - t) h <= h/4 in absolute value), where g' = d/dx (f - Hz f) =
//                     f_x - Hz f_x is itself a Hermite remainder (the cross derivative is exact),
//   so |f - Hx Hz f| <= h^4/384 (max|f_xxxx| + max|f_zzzz| + h/4 max|f_xzzzz|),
//   and for f = sum of m_f(k) h~(k) e^{i k.x}: max|d^a_x d^b_z f| <= sum |m_f h~| |kx|^a |kz|^b.
// The tangents and normal come from the interpolated slope and displacement-derivative
// fields (each with its own bound), not from differentiating the interpolated height.
//
// Periodic in x0 and z0 with the patch size, like the series. Memory: 32 doubles per sample
// (8 fields x 4 Hermite data), 256 MB for n = 256 and P = 4.
#pragma once

#include <cstdint>
#include <vector>

#include "engine/water/fft_ocean.hpp"

namespace vkw {

class SampledOceanSurface final : public WaterSurface {
public:
    // The ocean FftOceanSurface(spectrum, choppiness, level, time) sums exactly, sampled with
    // padding P: a power of two >= 1 (P n must be a power of two for the FFT); otherwise
    // vkw::InternalError.
    SampledOceanSurface(const FftOceanSpectrum& spectrum, double choppiness, double level, double time,
                        uint32_t padding);

    SurfacePoint at_parameter(double x0, double z0) const override;
    bool is_heightfield() const override { return heightfield_; }
    // A true bound on |h| of the interpolant from its node data: for one cell,
    // |Hx Hz f| <= max|f| + h/4 (max|f_x| + max|f_z|) + h^2/16 max|f_xz| (the bound on |Hx g|
    // of the header applied in x and in z), maxima over the nodes.
    double max_amplitude() const override { return amplitude_bound_; }

    // Every field of the interpolant at (x0, z0).
    OceanFieldValues fields_at(double x0, double z0) const;
    // The bound on |interpolant - series| of each field (header), plus rounding.
    const OceanFieldValues& error_bound() const { return error_bound_; }
    // The largest world-space slope |grad h| = |(n_x, n_z)| / n_y at the samples: the Lipschitz
    // constant of the height for stepping along rays (between samples the slope interpolant
    // may exceed it by its own error_bound, a small fraction of it).
    double max_sample_slope() const { return max_sample_slope_; }
    // 2 pi / the largest |k| of any nonzero mode: the shortest wave present, m.
    double shortest_wavelength() const { return shortest_wavelength_; }
    double period() const { return period_; }
    double spacing() const { return period_ / samples_; }
    uint32_t samples_per_side() const { return samples_; }
    double level() const { return level_; }

private:
    static constexpr uint32_t kHermiteData = 4;  // value, d/dx0, d/dz0, d2/dx0dz0
    const double* node(uint32_t ix, uint32_t iz) const {
        return nodes_.data() + (std::size_t(iz) * samples_ + ix) * kOceanFieldCount * kHermiteData;
    }

    uint32_t samples_ = 0;  // N = P n per side
    double period_ = 0.0, level_ = 0.0;
    bool heightfield_ = true;
    double amplitude_bound_ = 0.0, max_sample_slope_ = 0.0, shortest_wavelength_ = 0.0;
    OceanFieldValues error_bound_{};
    // N^2 nodes, row-major in z0 then x0; per node, per field, the kHermiteData values.
    std::vector<double> nodes_;
};

}  // namespace vkw
