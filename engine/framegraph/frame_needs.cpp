#include "engine/framegraph/frame_needs.hpp"

namespace vkw::fg {

bool FrameNeeds::needs(EffectTag effect) const {
    const EffectDecision* decision = find(effect);
    return decision == nullptr || decision->needed;
}

const EffectDecision* FrameNeeds::find(EffectTag effect) const {
    for (const EffectDecision& decision : decisions) {
        if (decision.effect == effect) return &decision;
    }
    return nullptr;
}

std::string FrameNeeds::describe() const {
    std::string text = "needs:\n";
    if (decisions.empty()) text += "  (no decisions: every effect is needed)\n";
    for (const EffectDecision& decision : decisions) {
        text += std::string("  ") + decision.effect.name + ": " + (decision.needed ? "on" : "off") +
                (decision.forced ? " (forced)" : "") + " - " + decision.reason + "\n";
    }
    return text;
}

void FrameNeeds::decide(EffectTag effect, bool needed, std::string reason, bool forced) {
    for (EffectDecision& decision : decisions) {
        if (decision.effect == effect) {
            decision = {effect, needed, forced, std::move(reason)};
            return;
        }
    }
    decisions.push_back({effect, needed, forced, std::move(reason)});
}

}  // namespace vkw::fg
