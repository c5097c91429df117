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

void FrameNeeds::decide(EffectTag effect, bool needed, std::string_view reason, bool forced) {
    decide_in_place(effect, needed, forced) = reason;
}

std::string& FrameNeeds::decide_in_place(EffectTag effect, bool needed, bool forced) {
    for (EffectDecision& decision : decisions) {
        if (decision.effect == effect) {
            decision.needed = needed;
            decision.forced = forced;
            decision.reason.clear();
            return decision.reason;
        }
    }
    EffectDecision& decision = decisions.emplace_back(EffectDecision{effect, needed, forced, {}});
    if (!spare_reasons_.empty()) {
        decision.reason = std::move(spare_reasons_.back());
        spare_reasons_.pop_back();
    }
    return decision.reason;
}

void FrameNeeds::clear() {
    // Taken back last first, so that each decision made again in the same order finds the string
    // its reason had last time.
    for (auto decision = decisions.rbegin(); decision != decisions.rend(); ++decision) {
        decision->reason.clear();
        spare_reasons_.push_back(std::move(decision->reason));
    }
    decisions.clear();
}

}  // namespace vkw::fg
