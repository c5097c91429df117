// Parameters of the three water-surface models (flat, sum of sines and Gerstner
// waves, Tessendorf FFT ocean). Plain data shared by the scene loader (which reads
// them from the scene file, `water.waves`) and the surface code (CPU evaluation in
// double precision here, GPU evaluation in a compute pass). Units: metres, seconds,
// degrees for angles in the file (radians nowhere in this struct's interface).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace vkw {

inline constexpr double kGravity = 9.81;  // m s^-2, for the deep-water dispersion omega^2 = g k

enum class WaveModel : uint8_t {
    Flat,      // h = 0
    Sum,       // sum of directional sines and Gerstner waves, analytic derivatives
    FftOcean,  // Tessendorf: h0 spectrum on the CPU (double), evolution + inverse FFT in compute
};

// One directional wave of a sum. steepness = 0 is a pure sine (a heightfield);
// steepness > 0 is a Gerstner (trochoidal) wave whose points also move horizontally
// (GPU Gems 1 ch. 1): its horizontal displacement amplitude is Q A = steepness / k, i.e.
// steepness = Q k A is the wave's own share of GPU Gems' global steepness (which splits
// one Q over N waves as Q / (k A N)). The horizontal Jacobian is then
// I - sum(steepness_i sin(theta_i) d_i d_i^T), so a steepness sum <= 1 guarantees no
// folding and a sum above 1 folds somewhere (engine/water/validate_waves.hpp).
struct WaveComponent {
    double amplitude = 0.0;      // m, >= 0
    double wavelength = 1.0;     // m, > 0
    double direction_deg = 0.0;  // direction of travel in the xz-plane, 0 = +x, 90 = +z
    double phase_deg = 0.0;      // phase offset
    double steepness = 0.0;  // 0: sine; (0, 1]: Gerstner (the total over all components <= 1 unless folding is allowed)
    double speed = -1.0;     // phase speed m/s; < 0: deep-water dispersion sqrt(g / k)

    bool operator==(const WaveComponent&) const = default;
};

enum class OceanSpectrum : uint8_t { Phillips, Jonswap };

struct FftOceanSettings {
    uint32_t resolution = 128;  // N x N grid, a power of two in [16, 1024]
    double patch_size = 64.0;   // m, the side of the periodic patch
    double wind_speed = 8.0;    // m/s at 10 m
    double wind_direction_deg = 0.0;
    OceanSpectrum spectrum = OceanSpectrum::Phillips;
    double fetch = 100000.0;       // m (JONSWAP only)
    double amplitude_scale = 1.0;  // multiplies the spectrum's amplitude
    double choppiness = 0.0;       // horizontal displacement scale (0: heightfield)

    bool operator==(const FftOceanSettings&) const = default;
};

struct WaveSettings {
    WaveModel model = WaveModel::Flat;
    std::vector<WaveComponent> components;  // WaveModel::Sum
    FftOceanSettings ocean;                 // WaveModel::FftOcean
    uint64_t seed = 1;                      // FFT ocean's initial spectrum
    bool allow_folding = false;             // lets Gerstner steepness sum exceed 1
};

// Gerstner waves fold (points overtake each other) when their steepness values sum to
// more than 1. The slack accepts components entered as exact fractions of 1 (ten waves
// of 0.1 sum to 1.0000000000000002). The one rule, used by the scene loader and by
// validate_waves.
inline constexpr double kSteepnessSumSlack = 1e-12;

inline double steepness_sum(const std::vector<WaveComponent>& components) {
    double sum = 0.0;
    for (const WaveComponent& wave : components) sum += wave.steepness;
    return sum;
}

inline bool steepness_folds(double sum) { return sum > 1.0 + kSteepnessSumSlack; }

}  // namespace vkw
