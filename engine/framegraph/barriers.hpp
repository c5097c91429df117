// Barrier derivation: a pure function from each resource's accesses, in execution
// order, to the barriers recorded before each pass (Granite's "invalidate" lists)
// and after the last one (imported resources handed back in a final state).
//
// Rules, per resource:
// - a write waits for the previous write and for every read since it (WAR needs only
//   an execution dependency, so reads add stages but no access);
// - a read waits for the last write, unless an earlier barrier since that write
//   already made it visible to the same stages and access in the same layout (the
//   barrier is then redundant and dropped);
// - a layout change always takes a barrier;
// - src access masks hold only write bits; stages are exact (never ALL_COMMANDS).
#pragma once

#include "engine/framegraph/access.hpp"

#include <optional>
#include <string>
#include <vector>

namespace vkw::fg {

struct TimelineAccess {
    uint32_t position;  // index of the pass in execution order
    AccessState state;  // merged over all uses of the resource within that pass
    bool writes;
};

struct ResourceTimeline {
    std::string name;
    bool is_image = true;
    // Before the first pass: transients start UNDEFINED (their old contents are
    // discarded) and wait for the last users of the memory they alias, if any;
    // imported resources start in the state their owner left them in.
    AccessState initial;
    std::vector<TimelineAccess> accesses;
    std::optional<AccessState> final_state;  // imported resources: the state to hand back
};

struct Barrier {
    uint32_t resource;  // index into the timelines
    bool is_image;
    AccessState src;
    AccessState dst;
};

struct BarrierPlan {
    std::vector<std::vector<Barrier>> before_pass;  // indexed by execution position
    std::vector<Barrier> after_last_pass;
};

BarrierPlan derive_barriers(const std::vector<ResourceTimeline>& timelines, size_t pass_count);

// One line per barrier:
//   before 'shade': image 'hdr' COLOR_ATTACHMENT_OUTPUT/COLOR_ATTACHMENT_WRITE -> FRAGMENT_SHADER/SHADER_SAMPLED_READ,
//   COLOR_ATTACHMENT_OPTIMAL -> SHADER_READ_ONLY_OPTIMAL
std::string describe(const Barrier& barrier, const std::vector<ResourceTimeline>& timelines);
std::string dump_barriers(const BarrierPlan& plan, const std::vector<ResourceTimeline>& timelines,
                          const std::vector<std::string>& pass_names);

}  // namespace vkw::fg
