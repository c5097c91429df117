// The settings of "effects.caustics" beside its mode (effects_json.cpp reads the mode): whether
// flat water keeps the exact stand-in, and the photons per water cell.
#include "engine/scene/scene_json.hpp"

namespace vkw {

CausticSettings read_caustic_settings(FieldReader& fields) {
    const CausticSettings defaults;
    CausticSettings caustics;
    caustics.analytic_flat = fields.boolean("analytic_flat", defaults.analytic_flat);
    caustics.sub_photons = static_cast<uint32_t>(
        fields.integer("sub_photons", Range::closed(1.0, 8.0, "photons per cell side"), defaults.sub_photons));
    caustics.jitter = fields.boolean("jitter", defaults.jitter);
    fields.finish();
    return caustics;
}

}  // namespace vkw
