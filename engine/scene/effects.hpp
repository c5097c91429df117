// The effects a scene can have, as scene files name them (effects.<name>) and as the frame's
// needs decide them. The frame graph knows none of them: a pass tags itself with one
// (fg::EffectTag, which takes any enum whose namespace provides effect_name), and the graph
// culls it when the decision for that tag is "not needed".
#pragma once

#include <array>
#include <cstdint>

namespace vkw {

enum class Effect : uint8_t {
    Water,                  // the water surface and its shading
    UnderwaterView,         // camera-medium split and the from-below path
    Reflection,             // the scene reflected in the water
    Refraction,             // the scene seen through the water
    RefractionSecondLayer,  // what the nearest receiver hides from the camera, seen through the water
    SurfaceCaustics,        // photon grid and splats on receivers
    VolumeCaustics,         // godray lines
    CausticBlur,            // blur of the caustic target
};

// Every effect, in declaration order.
inline constexpr std::array<Effect, 8> kAllEffects = {Effect::Water,
                                                      Effect::UnderwaterView,
                                                      Effect::Reflection,
                                                      Effect::Refraction,
                                                      Effect::RefractionSecondLayer,
                                                      Effect::SurfaceCaustics,
                                                      Effect::VolumeCaustics,
                                                      Effect::CausticBlur};

// The effect's name in scene files (effects.<name>) and reports.
constexpr const char* effect_name(Effect effect) {
    switch (effect) {
        case Effect::Water: return "water";
        case Effect::UnderwaterView: return "underwater_view";
        case Effect::Reflection: return "reflection";
        case Effect::Refraction: return "refraction";
        case Effect::RefractionSecondLayer: return "refraction_second_layer";
        case Effect::SurfaceCaustics: return "caustics";
        case Effect::VolumeCaustics: return "godrays";
        case Effect::CausticBlur: return "caustic_blur";
    }
    return "?";
}

}  // namespace vkw
