// The Tessendorf FFT ocean (J. Tessendorf, "Simulating Ocean Water", SIGGRAPH 2001 course
// notes): a periodic patch whose height is a Fourier series over the wave vectors
// k = 2 pi (fx, fz) / patch_size with integer frequencies -n/2 <= fx, fz < n/2:
//   h(x0, z0, t) = sum over k of h~(k, t) exp(i k . (x0, z0)),
//   h~(k, t)     = h0(k) exp(i w t) + conj(h0(-k)) exp(-i w t),  w = sqrt(g |k|),
//   h0(k)        = (xi_r + i xi_i) sqrt(Psi(k)) dk / 2,  dk = 2 pi / patch_size,
// xi_r, xi_i independent standard normals from the counter-based generator keyed by
// (seed, fx, fz) (counter_rng.hpp), Psi the variance density of ocean_spectrum.hpp. With this
// normalisation the expected <h^2> is the sum of Psi dk^2 over the modes (E|h0|^2 = Psi dk^2/2
// and each h~ collects two h0).
// Choppy waves displace horizontally by D = sum +i choppiness (k / |k|) h~ exp(i k . x);
// slopes are sum i k h~ exp(i k . x).
// The sign: for one cosine h = A cos(k x0) this gives D = -choppiness A sin(k x0), the
// trochoid, so choppiness > 0 squeezes the crests (sharp) and stretches the troughs, like
// a Gerstner wave of positive steepness. Tessendorf's notes print D = sum -i (k/|k|) h~
// exp(i k . x) and x + lambda D, which with lambda > 0 sharpens the troughs instead (hence
// the negative lambda of many implementations); here P = x0 - choppiness * (his D).
//
// Modes on the Nyquist row and column (fx or fz = -n/2) and k = 0 are zero: -k of a Nyquist
// mode is not on the grid, so keeping it would make the series complex between grid points.
// Without it h~(-k) = conj(h~(k)) exactly, the series is real everywhere, and the FFT grid
// (ocean_grid.hpp) equals the series at the grid points.
#pragma once

#include <array>
#include <complex>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <vector>

#include <glm/glm.hpp>

#include "engine/water/surface.hpp"
#include "engine/water/wave_params.hpp"

namespace vkw {

// The initial spectrum h0, computed once per (settings, seed) on the CPU in double precision
// and handed as is to the GPU, so both evaluate the same ocean.
struct FftOceanSpectrum {
    uint32_t n = 0;           // modes per axis (the grid resolution)
    double patch_size = 0.0;  // m, the period of the surface in x and z
    // h0 in FFT order, row-major: h0[b * n + a] is the mode with fx = frequency(a, n),
    // fz = frequency(b, n). m.
    std::vector<std::complex<double>> h0;

    // The signed frequency of array index i: i for i < n/2, i - n otherwise.
    static int frequency(uint32_t index, uint32_t n);
    glm::dvec2 wave_vector(uint32_t a, uint32_t b) const;  // rad/m
    std::size_t opposite(std::size_t index) const;         // the index of -k
    // 2 sum |h0|: bounds |h| at every time and place (each h~ is bounded by |h0(k)| + |h0(-k)|).
    double amplitude_bound() const;
    // sqrt(2 sum |h0|^2 |k|^4): the RMS, over the surface, of every second derivative of h (and
    // of the displacements over the choppiness), at every time (1/m). The surface is a Gaussian
    // random field, so it exceeds 4 times this on about 6e-5 of its area; the bound that holds
    // everywhere, 2 sum |h0| |k|^2, is tens of times larger on real spectra.
    double curvature_rms() const;
};

// Throws vkw::UserError (validate_ocean) for bad settings.
FftOceanSpectrum make_ocean_spectrum(const FftOceanSettings& ocean, uint64_t seed);

// make_ocean_spectrum, kept: h0 is a pure function of the settings that shape it (choppiness does
// not) and the seed, and the costliest part of a CPU ocean. The last spectrum is returned again
// while they stay the same, so a frame that needs the ocean several times (its bounds, the
// device copy) builds it once, and a caller can tell a new spectrum by its pointer. Thread-safe.
std::shared_ptr<const FftOceanSpectrum> shared_ocean_spectrum(const FftOceanSettings& ocean, uint64_t seed);

// Deep-water dispersion w = sqrt(g |k|), rad/s.
double ocean_angular_frequency(const glm::dvec2& k);

// h~(k, t) for every mode, in the layout of FftOceanSpectrum::h0.
std::vector<std::complex<double>> ocean_modes_at(const FftOceanSpectrum& spectrum, double time);

// The real fields the surface needs, each a Fourier series sum Re(m_f(k) h~(k) e^{ik.x}).
enum OceanField : uint32_t {
    kOceanHeight,   // h                  m_f = 1
    kOceanDispX,    // Dx                 i c kx / |k|
    kOceanDispZ,    // Dz                 i c kz / |k|
    kOceanSlopeX,   // dh/dx0             i kx
    kOceanSlopeZ,   // dh/dz0             i kz
    kOceanDispXdX,  // dDx/dx0            -c kx^2 / |k|
    kOceanDispXdZ,  // dDx/dz0 = dDz/dx0  -c kx kz / |k|
    kOceanDispZdZ,  // dDz/dz0            -c kz^2 / |k|
    kOceanFieldCount
};
using OceanFieldValues = std::array<double, kOceanFieldCount>;
using OceanFieldMultipliers = std::array<std::complex<double>, kOceanFieldCount>;

// m_f(k) for choppiness c (the table above; all zero at k = 0). Each satisfies
// m_f(-k) = conj(m_f(k)), which keeps every field real.
OceanFieldMultipliers ocean_field_multipliers(const glm::dvec2& k, double choppiness);

// Position, tangents and normal at parameter (x0, z0) from the field values there:
// P = (x0 + Dx, level + h, z0 + Dz), dP/du = (1 + dDx/dx0, dh/dx0, dDz/dx0), ...
SurfacePoint ocean_surface_point(const OceanFieldValues& f, double x0, double z0, double level);

}  // namespace vkw
