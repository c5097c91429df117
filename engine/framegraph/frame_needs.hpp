// What a frame needs: one decision per effect, each with a human-readable reason and
// whether the user forced it (effects.<name>.mode = on | off). The scene's needs
// function fills it; the frame graph culls every pass that serves an effect the
// frame does not need, and records that decision as the reason.
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <vector>

namespace vkw::fg {

enum class Effect : uint8_t {
    Water,            // the water surface and its shading
    UnderwaterView,   // stencil split and the from-below path
    Reflection,       // the scene reflected in the water
    Refraction,       // the scene seen through the water
    SurfaceCaustics,  // photon grid and splats on receivers
    VolumeCaustics,   // godray lines
    CausticBlur,      // blur of the caustic target
};

// Every effect, in declaration order, and its name in scene files (effects.<name>) and
// reports. constexpr in this header so that the scene loader can use them without
// linking the frame graph.
inline constexpr std::array<Effect, 7> kAllEffects = {Effect::Water,           Effect::UnderwaterView,
                                                      Effect::Reflection,      Effect::Refraction,
                                                      Effect::SurfaceCaustics, Effect::VolumeCaustics,
                                                      Effect::CausticBlur};

constexpr const char* effect_name(Effect effect) {
    switch (effect) {
        case Effect::Water: return "water";
        case Effect::UnderwaterView: return "underwater_view";
        case Effect::Reflection: return "reflection";
        case Effect::Refraction: return "refraction";
        case Effect::SurfaceCaustics: return "caustics";
        case Effect::VolumeCaustics: return "godrays";
        case Effect::CausticBlur: return "caustic_blur";
    }
    return "?";
}

struct EffectDecision {
    Effect effect;
    bool needed = true;
    bool forced = false;  // set by effects.<name>.mode = on | off rather than by a rule
    std::string reason;
};

struct FrameNeeds {
    std::vector<EffectDecision> decisions;

    // An effect with no decision is needed: passes are culled only for a stated reason.
    bool needs(Effect effect) const;
    const EffectDecision* find(Effect effect) const;
    void decide(Effect effect, bool needed, std::string reason, bool forced = false);
    // Which effects are on: two frames with the same key compile to the same graph.
    std::string key() const;
};

}  // namespace vkw::fg
