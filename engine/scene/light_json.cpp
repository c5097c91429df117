// The "sun" and "sky" sections of the scene schema. The sun's direction has two exclusive
// forms: elevation_deg/azimuth_deg (toward the sun, see direction_toward_sun) or direction
// (the travelling direction of the light, normalised here).
#include <array>

#include "engine/scene/direction.hpp"
#include "engine/scene/scene_json.hpp"

namespace vkw {
namespace {

constexpr std::string_view kSunForms = "either direction, or elevation_deg with optional azimuth_deg";

constexpr std::array<Named<SkyModel>, 2> kSkyModels = {{
    {"constant", SkyModel::Constant},
    {"gradient", SkyModel::Gradient},
}};

glm::dvec3 normalised_direction(FieldReader& fields, const glm::dvec3& given) {
    const std::optional<glm::dvec3> unit = unit_direction(given);
    if (!unit) fields.fail("direction", "[0, 0, 0] has no direction", "a non-zero vector with y < 0");
    const glm::dvec3 direction = *unit;
    if (!(direction.y < 0.0)) {
        fields.fail("direction",
                    format_vec3(given) +
                        " does not point downward; it is the direction the light travels, not the "
                        "direction toward the sun",
                    "a non-zero vector with y < 0, e.g. [0, -1, 0] for an overhead sun");
    }
    return direction;
}

}  // namespace

Sun read_sun(FieldReader& fields) {
    const Sun defaults;
    const auto direction = fields.optional_vec3("direction", Range::any());
    const Range elevation_range = Range::closed(-90.0, 90.0, "degrees");  // below the horizon lights nothing
    const auto elevation = fields.optional_number("elevation_deg", elevation_range);
    const auto azimuth = fields.optional_number("azimuth_deg", Range::closed(-360.0, 360.0, "degrees"));
    Sun sun;
    sun.irradiance = fields.vec3("irradiance", Range::radiometric("W m^-2"), defaults.irradiance);
    sun.shadow_texels = static_cast<uint32_t>(
        fields.integer("shadow_texels", Range::closed(16.0, 8192.0, "texels per side"), defaults.shadow_texels));
    // A misspelt "elevaton_deg" is the real reason when no form is found below.
    fields.finish();

    const bool angles = elevation.has_value() || azimuth.has_value();
    if (direction && angles) fields.fail("", "both direction and elevation_deg/azimuth_deg are given", kSunForms);
    if (!direction && !angles) fields.fail("", "no direction given", kSunForms);
    if (direction) {
        sun.direction = normalised_direction(fields, *direction);
    } else {
        // azimuth_deg alone does not place the sun; elevation is what matters most for lighting.
        if (!elevation) fields.fail("elevation_deg", "missing (azimuth_deg is given)", elevation_range.describe());
        sun.direction = -direction_toward_sun(*elevation, azimuth.value_or(0.0));
    }
    return sun;
}

// The sky's model decides its other fields: radiance for constant; zenith, horizon, ground and
// exponent for gradient. A field of the other model is then an unknown field.
Sky read_sky(FieldReader& fields) {
    const Sky defaults;
    const Range radiance = Range::radiometric("W m^-2 sr^-1");
    Sky sky;
    sky.model = fields.choice("model", kSkyModels, defaults.model);
    if (sky.model == SkyModel::Constant) {
        sky.radiance = fields.vec3("radiance", radiance);
        fields.belong_elsewhere({"zenith", "horizon", "ground", "exponent"},
                                "it belongs to the gradient sky: add \"model\": \"gradient\"");
        return sky;
    }
    fields.belong_elsewhere({"radiance"}, "it belongs to the constant sky: remove \"model\" or set it to \"constant\"");
    sky.zenith = fields.vec3("zenith", radiance);
    sky.horizon = fields.vec3("horizon", radiance);
    // The horizon's radiance continued below it: no step at the horizon.
    sky.ground = fields.vec3("ground", radiance, sky.horizon);
    sky.exponent = fields.number("exponent", Range::above(0.0), defaults.exponent);
    return sky;
}

}  // namespace vkw
