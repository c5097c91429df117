// The "effects" section of the scene schema: one optional object per frame-graph effect, named
// as vkw::effect_name() names it, each with a mode.
#include <array>

#include "engine/scene/scene_json.hpp"

namespace vkw {
namespace {

// The effect names as the reader's choice table, built from the frame graph's own list.
constexpr std::array<Named<Effect>, kEffectCount> effect_names() {
    std::array<Named<Effect>, kEffectCount> names{};
    for (size_t i = 0; i < kEffectCount; ++i) names[i] = {effect_name(kAllEffects[i]), kAllEffects[i]};
    return names;
}
constexpr std::array<Named<Effect>, kEffectCount> kEffects = effect_names();

constexpr std::array<Named<EffectMode>, 3> kModes = {{
    {"auto", EffectMode::Auto},
    {"on", EffectMode::On},
    {"off", EffectMode::Off},
}};

constexpr std::array<Named<SceneLookup>, 2> kLookups = {{
    {"projective", SceneLookup::Projective},
    {"screen_space", SceneLookup::ScreenSpace},
}};

EffectSettings read_effect(FieldReader& fields) {
    const EffectSettings defaults;
    EffectSettings effect;
    effect.mode = fields.choice("mode", kModes, defaults.mode);
    return effect;
}

// reflection and refraction: how the scene is found along the ray, and how hard to look.
EffectSettings read_scene_lookup_effect(FieldReader& fields) {
    EffectSettings effect = read_effect(fields);
    effect.method = fields.choice("method", kLookups, effect.method);
    effect.max_steps =
        static_cast<int>(fields.integer("max_steps", Range::closed(1.0, 256.0, "steps"), effect.max_steps));
    return effect;
}

EffectSettings read_refraction_effect(FieldReader& fields) {
    EffectSettings effect = read_scene_lookup_effect(fields);
    effect.shallow_blend = fields.number("shallow_blend", Range::closed(0.0, 10.0, "m"), effect.shallow_blend);
    return effect;
}

constexpr std::array<Named<SurfaceFresnel>, 3> kFresnels = {{
    {"exact", SurfaceFresnel::Exact},
    {"schlick", SurfaceFresnel::Schlick},
    {"power", SurfaceFresnel::Power},
}};

DepthBlend read_depth_blend(FieldReader& fields) {
    const DepthBlend defaults;
    DepthBlend blend;
    blend.colour = fields.vec3("colour", Range::closed(0.0, 1e6, "W m^-2 sr^-1"), defaults.colour);
    blend.k = fields.number("k", Range::closed(0.0, 100.0, "1/m"), defaults.k);
    return blend;
}

// water: the surface's shading (the Fresnel form, Optical Phenomena c. 2008's depth colour).
WaterShadingSettings read_water_shading(FieldReader& fields) {
    const WaterShadingSettings defaults;
    WaterShadingSettings shading;
    shading.fresnel = fields.choice("fresnel", kFresnels, defaults.fresnel);
    shading.fresnel_power =
        fields.number("fresnel_power", Range::closed(1.0, 10.0, "exponent q"), defaults.fresnel_power);
    if (fields.has("depth_blend")) {
        shading.depth_blend = fields.object("depth_blend", Presence::optional, read_depth_blend);
    }
    shading.glitter = fields.boolean("glitter", defaults.glitter);
    return shading;
}

}  // namespace

EffectsSettings read_effects(FieldReader& fields) {
    EffectsSettings effects;
    for (const Named<Effect>& effect : kEffects) {
        // Effects with settings of their own beside the mode: the mode is read first, then their
        // reader takes the rest (and finishes the object, refusing unknown fields).
        const auto with_settings = [&](auto read_settings, auto& settings) {
            effects[effect.value] = fields.object(effect.name, Presence::optional, [&](FieldReader& object) {
                const EffectSettings mode = read_effect(object);
                settings = read_settings(object);
                return mode;
            });
        };
        if (effect.value == Effect::Water) {
            with_settings(read_water_shading, effects.water);
            continue;
        }
        if (effect.value == Effect::VolumeCaustics) {
            with_settings(read_godray_settings, effects.godrays);
            continue;
        }
        if (effect.value == Effect::SurfaceCaustics) {
            with_settings(read_caustic_settings, effects.caustics);
            continue;
        }
        if (effect.value == Effect::CausticBlur) {
            with_settings(read_caustic_blur_settings, effects.caustic_blur);
            continue;
        }
        const auto reader = effect.value == Effect::Reflection   ? read_scene_lookup_effect
                            : effect.value == Effect::Refraction ? read_refraction_effect
                                                                 : read_effect;
        effects[effect.value] = fields.object(effect.name, Presence::optional, reader);
    }
    return effects;
}

}  // namespace vkw
