// The FFT ocean on its grid (ocean_grid.hpp).
#include "engine/water/ocean_grid.hpp"

#include <algorithm>
#include <cmath>
#include <complex>
#include <cstddef>

#include "engine/water/fft.hpp"

namespace vkw {

OceanFieldValues FftOceanGrid::values(uint32_t ix, uint32_t iz) const {
    OceanFieldValues v{};
    const std::size_t index = std::size_t(iz) * n + ix;
    for (uint32_t f = 0; f < kOceanFieldCount; ++f) {
        v[f] = fields[f][index];
    }
    return v;
}

SurfacePoint FftOceanGrid::point(uint32_t ix, uint32_t iz, double level) const {
    return ocean_surface_point(values(ix, iz), ix * spacing(), iz * spacing(), level);
}

double FftOceanGrid::max_abs_height() const {
    double m = 0.0;
    for (double h : fields[kOceanHeight]) {
        m = std::max(m, std::abs(h));
    }
    return m;
}

FftOceanGrid evaluate_ocean_grid(const FftOceanSpectrum& spectrum, double choppiness, double time) {
    FftOceanGrid grid;
    grid.n = spectrum.n;
    grid.patch_size = spectrum.patch_size;
    grid.time = time;
    grid.choppiness = choppiness;
    const uint32_t n = spectrum.n;
    const std::vector<std::complex<double>> modes = ocean_modes_at(spectrum, time);
    std::vector<OceanFieldMultipliers> multipliers(modes.size());
    for (uint32_t b = 0; b < n; ++b) {
        for (uint32_t a = 0; a < n; ++a) {
            multipliers[std::size_t(b) * n + a] = ocean_field_multipliers(spectrum.wave_vector(a, b), choppiness);
        }
    }
    std::vector<std::complex<double>> work(modes.size());
    for (uint32_t f = 0; f < kOceanFieldCount; ++f) {
        for (std::size_t i = 0; i < modes.size(); ++i) {
            work[i] = multipliers[i][f] * modes[i];
        }
        fft_inverse_2d(work, n);
        grid.fields[f].resize(modes.size());
        for (std::size_t i = 0; i < modes.size(); ++i) {
            grid.fields[f][i] = work[i].real();
        }
    }
    return grid;
}

}  // namespace vkw
