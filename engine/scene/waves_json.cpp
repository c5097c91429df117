// "water.waves": the surface model and its parameters, into vkw::WaveSettings
// (engine/water/wave_params.hpp). The model decides which fields exist: those of another model
// are unknown fields.
#include <array>
#include <bit>

#include "engine/scene/scene_json.hpp"

namespace vkw {

// The Phillips spectrum's largest wave is V^2 / g: at most kMaxSceneLength for V <= 990 m/s.
constexpr double kMaxWindSpeed = 990.0;

namespace {

constexpr std::array<Named<WaveModel>, 3> kModels = {{
    {"flat", WaveModel::Flat},
    {"sum", WaveModel::Sum},
    {"fft", WaveModel::FftOcean},
}};

constexpr std::array<Named<OceanSpectrum>, 2> kSpectra = {{
    {"phillips", OceanSpectrum::Phillips},
    {"jonswap", OceanSpectrum::Jonswap},
}};

// The fields of the sum and fft models, none of which a flat surface has.
constexpr std::array<std::string_view, 10> kModelFields = {
    "components",         "allow_folding", "resolution", "patch_size",      "wind_speed",
    "wind_direction_deg", "spectrum",      "fetch",      "amplitude_scale", "choppiness"};

WaveComponent read_component(FieldReader& fields) {
    const WaveComponent defaults;
    WaveComponent wave;
    wave.amplitude = fields.number("amplitude", Range::nonnegative_length());
    wave.wavelength = fields.number("wavelength", Range::positive_length());
    const Range angle = Range::closed(-360.0, 360.0, "degrees");
    wave.direction_deg = fields.number("direction_deg", angle, defaults.direction_deg);
    wave.phase_deg = fields.number("phase_deg", angle, defaults.phase_deg);
    wave.steepness = fields.number("steepness", Range::closed(0.0, 1.0), defaults.steepness);
    // Omitted: the deep-water dispersion speed, which WaveComponent marks with a negative value.
    wave.speed =
        fields
            .optional_number("speed", Range{.min = 0.0, .max = kMaxSceneLength, .min_inclusive = false, .unit = "m/s"})
            .value_or(defaults.speed);
    return wave;
}

void read_sum(FieldReader& fields, WaveSettings& waves) {
    waves.components = fields.objects("components", read_component);
    waves.allow_folding = fields.boolean("allow_folding", false);
    fields.finish();
    if (waves.components.empty()) {
        const std::string what = fields.has("components") ? "is empty" : "missing required field";
        fields.fail("components", what, "an array of at least one wave component");
    }
    const double steepness = steepness_sum(waves.components);
    if (steepness_folds(steepness) && !waves.allow_folding) {
        fields.fail("components",
                    "the Gerstner steepness values sum to " + format_number(steepness) + ", so the surface folds",
                    "sum of steepness <= 1, or allow_folding: true");
    }
}

void read_fft(FieldReader& fields, FftOceanSettings& ocean) {
    const FftOceanSettings defaults;
    const Range resolution_range = Range::closed(16.0, 1024.0);
    const auto resolution = fields.integer("resolution", resolution_range, defaults.resolution);
    if (!std::has_single_bit(static_cast<uint64_t>(resolution))) {
        fields.fail("resolution", std::to_string(resolution) + " is not a power of two",
                    "a power of two, " + resolution_range.describe());
    }
    ocean.resolution = static_cast<uint32_t>(resolution);
    ocean.patch_size = fields.number("patch_size", Range::positive_length(), defaults.patch_size);
    ocean.wind_speed =
        fields.number("wind_speed", Range{.min = 0.0, .max = kMaxWindSpeed, .min_inclusive = false, .unit = "m/s"},
                      defaults.wind_speed);
    ocean.wind_direction_deg =
        fields.number("wind_direction_deg", Range::closed(-360.0, 360.0, "degrees"), defaults.wind_direction_deg);
    ocean.spectrum = fields.choice("spectrum", kSpectra, defaults.spectrum);
    ocean.fetch = fields.number("fetch", Range::positive_length(), defaults.fetch);
    ocean.amplitude_scale = fields.number("amplitude_scale", Range::closed(0.0, 1e3), defaults.amplitude_scale);
    ocean.choppiness = fields.number("choppiness", Range::closed(0.0, 1e3), defaults.choppiness);
    fields.finish();
    // Phillips has no fetch: a fetch there would be silently ignored.
    if (fields.has("fetch") && ocean.spectrum != OceanSpectrum::Jonswap) {
        fields.fail("fetch", "is only used by the jonswap spectrum", "fetch only with spectrum: jonswap");
    }
}

}  // namespace

WaveSettings read_waves(FieldReader& fields) {
    WaveSettings waves;
    const auto model = fields.optional_choice("model", kModels);
    if (!model) {
        // "flat" by default; a field of another model without its model is a forgotten model.
        for (const std::string_view key : kModelFields) fields.declare({key});
        fields.finish();
        for (const std::string_view key : kModelFields) {
            if (!fields.has(key)) continue;
            std::vector<std::string_view> names;
            for (const Named<WaveModel>& option : kModels) names.push_back(option.name);
            fields.fail("model", "missing (" + std::string(key) + " is given)", one_of(names));
        }
        return waves;
    }
    waves.model = *model;
    if (waves.model == WaveModel::Sum) read_sum(fields, waves);
    if (waves.model == WaveModel::FftOcean) read_fft(fields, waves.ocean);
    return waves;
}

}  // namespace vkw
