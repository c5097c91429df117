// What a frame needs: one decision per effect, each with a human-readable reason and
// whether the user forced it. The layer that composes the frame fills it; the frame graph
// culls every pass that serves an effect the frame does not need, and records that decision
// as the reason. The graph knows no effect by name: an effect is an opaque tag.
#pragma once

#include <concepts>
#include <cstdint>
#include <string>
#include <string_view>
#include <type_traits>
#include <vector>

namespace vkw::fg {

// An effect as the graph sees it: an id to compare and a name to print. Any enum whose
// namespace provides `const char* effect_name(E)` converts to a tag, so the composing layer
// keeps its own enum and the graph stays free of it.
struct EffectTag {
    uint32_t id = 0;
    const char* name = "";

    constexpr EffectTag() = default;
    constexpr EffectTag(uint32_t tag_id, const char* tag_name) : id(tag_id), name(tag_name) {}
    template <typename E>
    requires std::is_enum_v<E> && requires(E e) {
        { effect_name(e) } -> std::convertible_to<const char*>;
    }
    constexpr EffectTag(E effect) : id(static_cast<uint32_t>(effect)), name(effect_name(effect)) {}

    // The name takes part so that two enums' values with the same number stay apart.
    friend bool operator==(const EffectTag& a, const EffectTag& b) {
        return a.id == b.id && std::string_view(a.name) == b.name;
    }
};

struct EffectDecision {
    EffectTag effect;
    bool needed = true;
    bool forced = false;  // set by the user (a scene's effects.<name>.mode = on | off) rather than by a rule
    std::string reason;
};

struct FrameNeeds {
    std::vector<EffectDecision> decisions;

    // An effect with no decision is needed: passes are culled only for a stated reason.
    bool needs(EffectTag effect) const;
    const EffectDecision* find(EffectTag effect) const;
    void decide(EffectTag effect, bool needed, std::string_view reason, bool forced = false);
    // The same, returning the decision's reason empty for the caller to write in place. A decision
    // made again for the same effect replaces the earlier one.
    std::string& decide_in_place(EffectTag effect, bool needed, bool forced = false);
    // Forgets every decision but keeps their reasons' storage, which the next decisions write
    // again: the renderer decides every frame's needs into the last one's, and the reasons' strings
    // were most of the heap allocations of a frame's declaration.
    void clear();
    // "needs:" and one line per decision: "  effect: on|off [(forced)] - reason".
    std::string describe() const;

private:
    std::vector<std::string> spare_reasons_;  // cleared, with their capacity
};

}  // namespace vkw::fg
