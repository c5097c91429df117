// make_surface: picks the model of a WaveSettings (surface.hpp).
#include <cmath>
#include <limits>
#include <memory>
#include <mutex>
#include <vector>

#include "engine/core/errors.hpp"
#include "engine/water/fft_ocean_surface.hpp"
#include "engine/water/flat_surface.hpp"
#include "engine/water/surface.hpp"
#include "engine/water/validate_waves.hpp"
#include "engine/water/wave_sum_surface.hpp"

namespace vkw {

std::unique_ptr<WaterSurface> make_surface(const WaveSettings& settings, double level, double time) {
    if (!std::isfinite(level) || !std::isfinite(time)) {
        throw InternalError("make_surface: the water level and the time must be finite");
    }
    validate_waves(settings);
    switch (settings.model) {
        case WaveModel::Flat: return std::make_unique<FlatSurface>(level);
        case WaveModel::Sum: return std::make_unique<WaveSumSurface>(settings, level, time);
        case WaveModel::FftOcean: {
            return std::make_unique<FftOceanSurface>(shared_ocean_spectrum(settings.ocean, settings.seed),
                                                     settings.ocean.choppiness, level, time);
        }
    }
    throw InternalError("make_surface: unknown wave model");
}

double frame_amplitude_bound(const WaveSettings& settings, double level, double time) {
    if (!std::isfinite(level) || !std::isfinite(time)) {
        throw InternalError("frame_amplitude_bound: the water level and the time must be finite");
    }
    validate_waves(settings);
    // What FlatSurface and WaveSumSurface::max_amplitude give, without building the surface: the
    // renderer asks several times a frame, and each build allocated.
    if (settings.model == WaveModel::Flat) return 0.0;
    if (settings.model == WaveModel::Sum) {
        double amplitude_sum = 0.0;
        for (const WaveComponent& c : settings.components) amplitude_sum += c.amplitude;
        return amplitude_sum;
    }
    const std::shared_ptr<const FftOceanSpectrum> spectrum = shared_ocean_spectrum(settings.ocean, settings.seed);
    // The last spectrum's bound, kept with the spectrum itself (holding it keeps its address
    // from being reused by another).
    static std::mutex mutex;
    static std::shared_ptr<const FftOceanSpectrum> last;
    static double last_bound = 0.0;
    const std::lock_guard lock(mutex);
    if (last != spectrum) {
        last_bound = spectrum->amplitude_bound();
        last = spectrum;
    }
    return last_bound;
}

ShapeBounds frame_shape_bounds(const WaveSettings& settings, double level, double time) {
    if (settings.model == WaveModel::FftOcean) {
        return {std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity()};
    }
    if (settings.model == WaveModel::Flat) {
        validate_waves(settings);
        return {};
    }
    thread_local bool kept = false;
    thread_local std::vector<WaveComponent> kept_components;
    thread_local bool kept_allow_folding = false;
    thread_local ShapeBounds kept_bounds;
    if (kept && kept_components == settings.components && kept_allow_folding == settings.allow_folding &&
        std::isfinite(level) && std::isfinite(time)) {
        return kept_bounds;
    }
    kept = false;  // until the new bounds are made: make_surface may throw
    const std::unique_ptr<WaterSurface> surface = make_surface(settings, level, time);
    kept_bounds = {surface->max_slope(), surface->max_curvature()};
    kept_components = settings.components;
    kept_allow_folding = settings.allow_folding;
    kept = true;
    return kept_bounds;
}

}  // namespace vkw
