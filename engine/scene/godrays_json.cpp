// The settings of "effects.godrays" beside its mode (effects_json.cpp reads the mode): the
// photon grid of the beams, the resolution they are gathered at, where beams stop, and the
// method (lines, or the marched baseline with its step count).
#include <array>

#include "engine/scene/scene_json.hpp"

namespace vkw {
namespace {

constexpr std::array<Named<GodrayMethod>, 2> kMethods = {{
    {"lines", GodrayMethod::Lines},
    {"marched", GodrayMethod::Marched},
}};

}  // namespace

GodraySettings read_godray_settings(FieldReader& fields) {
    const GodraySettings defaults;
    GodraySettings godrays;
    // 1024^2 beams of 48 bytes fill 48 MiB, within one storage binding (128 MiB on lavapipe).
    godrays.grid =
        static_cast<uint32_t>(fields.integer("grid", Range::closed(2.0, 1024.0, "beams per side"), defaults.grid));
    godrays.resolution_scale = fields.number("resolution_scale", Range::closed(0.5, 1.0), defaults.resolution_scale);
    godrays.max_depth = fields.optional_number("max_depth", Range::positive_length());
    godrays.method = fields.choice("method", kMethods, defaults.method);
    godrays.march_steps =
        static_cast<uint32_t>(fields.integer("march_steps", Range::closed(1.0, 4096.0, "steps"), defaults.march_steps));
    fields.finish();  // a misspelt key explains more than a value out of the set
    // Two sizes only: the full output, or half of it per side (de la Fuente 2011's godray buffer).
    if (godrays.resolution_scale != 0.5 && godrays.resolution_scale != 1.0) {
        fields.fail("resolution_scale", format_number(godrays.resolution_scale) + " is not one of the two sizes",
                    "0.5 or 1");
    }
    return godrays;
}

}  // namespace vkw
