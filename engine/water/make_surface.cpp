// make_surface: picks the model of a WaveSettings (surface.hpp).
#include <cmath>
#include <memory>

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

}  // namespace vkw
