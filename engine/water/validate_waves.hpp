// Checks of the wave parameters that the surface models rely on, with errors worded for
// the user: each names the scene field (`water.waves.components[i].steepness`,
// `water.waves.resolution`, ... as engine/scene/waves_json.cpp lays `water.waves` out), the
// value and the accepted range. The surface constructors call it, so no surface is ever
// built from settings that would give NaN or a silently folded mesh; the scene loader's
// checks are at least as strict.
#pragma once

#include "engine/water/wave_params.hpp"

namespace vkw {

// Throws vkw::UserError for the first bad field. For WaveModel::Sum:
//   amplitude >= 0 m, wavelength > 0 m, direction/phase/speed finite, steepness >= 0, and
//   the steepness sum over all waves <= 1 unless allow_folding (the sum may exceed 1 by
//   1e-12 for rounding, so that e.g. ten waves of 0.1 pass). The error names the wave at
//   which the running sum first exceeds 1.
// For WaveModel::FftOcean: validate_ocean. WaveModel::Flat has nothing to check.
void validate_waves(const WaveSettings& settings);

// The WaveModel::Sum checks of validate_waves on `settings.components`, whatever its model.
void validate_wave_components(const WaveSettings& settings);

// resolution a power of two in [16, 1024]; patch_size > 0 m; wind_speed > 0 m/s;
// wind_direction_deg finite; fetch > 0 m; amplitude_scale >= 0; choppiness >= 0.
// (A large choppiness folds the ocean; that is not checked: it depends on the realisation.)
void validate_ocean(const FftOceanSettings& ocean);

}  // namespace vkw
