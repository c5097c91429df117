// The "effects" section of the scene schema: one optional object per frame-graph effect, named
// as vkw::fg::effect_name() names it (tests/scene check the two agree), each with a mode.
#include <array>

#include "engine/scene/scene_json.hpp"

namespace vkw {
namespace {

constexpr std::array<Named<fg::Effect>, kEffectCount> kEffects = {{
    {"water", fg::Effect::Water},
    {"underwater_view", fg::Effect::UnderwaterView},
    {"reflection", fg::Effect::Reflection},
    {"refraction", fg::Effect::Refraction},
    {"caustics", fg::Effect::SurfaceCaustics},
    {"godrays", fg::Effect::VolumeCaustics},
    {"caustic_blur", fg::Effect::CausticBlur},
}};

constexpr std::array<Named<EffectMode>, 3> kModes = {{
    {"auto", EffectMode::Auto},
    {"on", EffectMode::On},
    {"off", EffectMode::Off},
}};

EffectSettings read_effect(FieldReader& fields) {
    const EffectSettings defaults;
    EffectSettings effect;
    effect.mode = fields.choice("mode", kModes, defaults.mode);
    return effect;
}

}  // namespace

EffectsSettings read_effects(FieldReader& fields) {
    EffectsSettings effects;
    for (const Named<fg::Effect>& effect : kEffects) {
        effects[effect.value] = fields.object(effect.name, Presence::optional, read_effect);
    }
    return effects;
}

}  // namespace vkw
