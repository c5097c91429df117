// The FFT ocean as a WaterSurface: at_parameter sums the Fourier series of fft_ocean.hpp
// exactly at any (x0, z0) (n^2 modes per point: slow, but exact between grid points and the
// reference the grid and the GPU are tested against). For many points on the grid use
// grid() (ocean_grid.hpp), which agrees with this at the grid nodes to rounding.
// The surface is periodic in x0 and z0 with the patch size.
#pragma once

#include <complex>
#include <memory>
#include <vector>

#include "engine/water/fft_ocean.hpp"
#include "engine/water/ocean_grid.hpp"

namespace vkw {

class FftOceanSurface final : public WaterSurface {
public:
    // `spectrum` is shared so that the frames of an animation reuse one h0.
    FftOceanSurface(std::shared_ptr<const FftOceanSpectrum> spectrum, double choppiness, double level, double time);

    SurfacePoint at_parameter(double x0, double z0) const override;
    bool is_heightfield() const override { return choppiness_ == 0.0; }
    // sum |h~(k, t)| over the modes: a true bound on |h| at this surface's time (tighter
    // than the all-time spectrum().amplitude_bound(), and still several times the largest
    // height actually reached, since the phases rarely align).
    double max_amplitude() const override { return amplitude_bound_; }

    // All fields of the series at (x0, z0).
    OceanFieldValues fields_at(double x0, double z0) const;
    FftOceanGrid grid() const;
    const FftOceanSpectrum& spectrum() const { return *spectrum_; }
    double time() const { return time_; }
    double level() const { return level_; }

private:
    std::shared_ptr<const FftOceanSpectrum> spectrum_;
    double choppiness_;
    double level_;
    double time_;
    std::vector<std::complex<double>> modes_;  // h~(k, t), FftOceanSpectrum layout
    double amplitude_bound_ = 0.0;
};

}  // namespace vkw
