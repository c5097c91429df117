// make_surface: picks the model of a WaveSettings (surface.hpp).
#include <cmath>
#include <memory>
#include <mutex>
#include <optional>
#include <utility>

#include "engine/core/errors.hpp"
#include "engine/water/fft_ocean_surface.hpp"
#include "engine/water/flat_surface.hpp"
#include "engine/water/surface.hpp"
#include "engine/water/validate_waves.hpp"
#include "engine/water/wave_sum_surface.hpp"

namespace vkw {

namespace {

// The initial spectrum is a pure function of the ocean's settings and seed, and by far the
// costliest part of a CPU ocean surface (its random modes and the spectrum's powers): the last
// one is kept, so that a frame asking for the surface several times (its bounds for the needs,
// the caustic map and the godrays) builds it once. Thread-safe: the reference renders on threads.
std::shared_ptr<const FftOceanSpectrum> ocean_spectrum(const FftOceanSettings& ocean, uint64_t seed) {
    static std::mutex mutex;
    static std::optional<std::pair<FftOceanSettings, uint64_t>> last_key;
    static std::shared_ptr<const FftOceanSpectrum> last;
    const std::lock_guard lock(mutex);
    if (!last_key || last_key->first != ocean || last_key->second != seed) {
        last = std::make_shared<const FftOceanSpectrum>(make_ocean_spectrum(ocean, seed));
        last_key = std::make_pair(ocean, seed);
    }
    return last;
}

}  // namespace

std::unique_ptr<WaterSurface> make_surface(const WaveSettings& settings, double level, double time) {
    if (!std::isfinite(level) || !std::isfinite(time)) {
        throw InternalError("make_surface: the water level and the time must be finite");
    }
    validate_waves(settings);
    switch (settings.model) {
        case WaveModel::Flat: return std::make_unique<FlatSurface>(level);
        case WaveModel::Sum: return std::make_unique<WaveSumSurface>(settings, level, time);
        case WaveModel::FftOcean: {
            return std::make_unique<FftOceanSurface>(ocean_spectrum(settings.ocean, settings.seed),
                                                     settings.ocean.choppiness, level, time);
        }
    }
    throw InternalError("make_surface: unknown wave model");
}

}  // namespace vkw
