// The "effects" section of the scene schema: one optional object per frame-graph effect, named
// as vkw::fg::effect_name() names it, each with a mode.
#include <array>

#include "engine/scene/scene_json.hpp"

namespace vkw {
namespace {

// The effect names as the reader's choice table, built from the frame graph's own list.
constexpr std::array<Named<fg::Effect>, kEffectCount> effect_names() {
    std::array<Named<fg::Effect>, kEffectCount> names{};
    for (size_t i = 0; i < kEffectCount; ++i) names[i] = {fg::effect_name(fg::kAllEffects[i]), fg::kAllEffects[i]};
    return names;
}
constexpr std::array<Named<fg::Effect>, kEffectCount> kEffects = effect_names();

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
