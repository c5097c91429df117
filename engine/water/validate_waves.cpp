// The wave-parameter checks of validate_waves.hpp.
#include "engine/water/validate_waves.hpp"

#include <charconv>
#include <cmath>
#include <cstddef>
#include <string>

#include "engine/core/errors.hpp"

namespace vkw {

namespace {

// Shortest text that reads back as the same double.
std::string number(double value) {
    char buffer[64];
    const auto result = std::to_chars(buffer, buffer + sizeof buffer, value);
    return std::string(buffer, result.ptr);
}

std::string wave_field(std::size_t index, const char* name) {
    return "water.waves.components[" + std::to_string(index) + "]." + name;
}

[[noreturn]] void refuse(const std::string& field, double value, const std::string& accepted) {
    throw UserError(field + " = " + number(value) + ": accepted " + accepted);
}

// Refuses `value` unless it is finite and `ok` holds.
void require(bool ok, const std::string& field, double value, const std::string& accepted) {
    if (!std::isfinite(value) || !ok) {
        refuse(field, value, accepted);
    }
}

void require_finite(const std::string& field, double value, const std::string& accepted) {
    require(true, field, value, accepted);
}

// The same for component `index`'s field `name`. The field's text is made only for the error:
// the renderer builds its surfaces several times a frame, and valid components must cost no
// allocation.
void require_component(bool ok, std::size_t index, const char* name, double value, const char* accepted) {
    if (!std::isfinite(value) || !ok) {
        refuse(wave_field(index, name), value, accepted);
    }
}

bool is_power_of_two(uint32_t n) { return n != 0 && (n & (n - 1)) == 0; }

}  // namespace

void validate_ocean(const FftOceanSettings& ocean) {
    if (!is_power_of_two(ocean.resolution) || ocean.resolution < 16 || ocean.resolution > 1024) {
        throw UserError("water.waves.resolution = " + std::to_string(ocean.resolution) +
                        ": accepted a power of two in [16, 1024]");
    }
    require(ocean.patch_size > 0.0, "water.waves.patch_size", ocean.patch_size, "value > 0 m");
    require(ocean.wind_speed > 0.0, "water.waves.wind_speed", ocean.wind_speed, "value > 0 m/s");
    require_finite("water.waves.wind_direction_deg", ocean.wind_direction_deg, "any finite value (degrees)");
    require(ocean.fetch > 0.0, "water.waves.fetch", ocean.fetch, "value > 0 m");
    require(ocean.amplitude_scale >= 0.0, "water.waves.amplitude_scale", ocean.amplitude_scale, "value >= 0");
    require(ocean.choppiness >= 0.0, "water.waves.choppiness", ocean.choppiness, "value >= 0");
}

void validate_wave_components(const WaveSettings& settings) {
    double steepness_sum = 0.0;
    for (std::size_t i = 0; i < settings.components.size(); ++i) {
        const WaveComponent& w = settings.components[i];
        require_component(w.amplitude >= 0.0, i, "amplitude", w.amplitude, "value >= 0 m");
        require_component(w.wavelength > 0.0, i, "wavelength", w.wavelength, "value > 0 m");
        require_component(true, i, "direction_deg", w.direction_deg, "any finite value (degrees)");
        require_component(true, i, "phase_deg", w.phase_deg, "any finite value (degrees)");
        require_component(true, i, "speed", w.speed, "any finite value (m/s; < 0: deep-water dispersion sqrt(g / k))");
        require_component(w.steepness >= 0.0, i, "steepness", w.steepness, "value >= 0 (0: sine; > 0: Gerstner)");
        steepness_sum += w.steepness;
        if (!settings.allow_folding && steepness_folds(steepness_sum)) {
            throw UserError(wave_field(i, "steepness") + " = " + number(w.steepness) +
                            ": the steepness of water.waves.components[0.." + std::to_string(i) + "] sums to " +
                            number(steepness_sum) +
                            "; accepted 0 <= steepness with a sum over all waves <= 1 "
                            "(above 1 the waves fold; set water.waves.allow_folding to allow it)");
        }
    }
}

void validate_waves(const WaveSettings& settings) {
    switch (settings.model) {
        case WaveModel::Flat: return;
        case WaveModel::Sum: validate_wave_components(settings); return;
        case WaveModel::FftOcean: validate_ocean(settings.ocean); return;
    }
}

}  // namespace vkw
