#include "engine/framegraph/barriers.hpp"

namespace vkw::fg {
namespace {

constexpr VkAccessFlags2 kWriteAccess = VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT | VK_ACCESS_2_COLOR_ATTACHMENT_WRITE_BIT |
                                        VK_ACCESS_2_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT |
                                        VK_ACCESS_2_TRANSFER_WRITE_BIT | VK_ACCESS_2_HOST_WRITE_BIT |
                                        VK_ACCESS_2_SHADER_WRITE_BIT | VK_ACCESS_2_MEMORY_WRITE_BIT;

// What one resource has seen so far while walking its timeline.
struct Tracker {
    AccessState last_write;                    // stages + write access of the last writer
    VkPipelineStageFlags2 read_stages = 0;     // stages that read since that write
    VkPipelineStageFlags2 visible_stages = 0;  // the last write is visible to these...
    VkAccessFlags2 visible_access = 0;         // ...for these accesses
    VkImageLayout layout = VK_IMAGE_LAYOUT_UNDEFINED;
};

// The barrier that moves `tracker` to `next`, or nothing when none is needed.
std::optional<Barrier> step(Tracker& tracker, const AccessState& next, bool writes, uint32_t resource, bool is_image) {
    const bool layout_change = is_image && tracker.layout != next.layout;
    Barrier barrier{resource, is_image, {}, next};
    barrier.src.stages = tracker.last_write.stages | tracker.read_stages;
    barrier.src.access = tracker.last_write.access & kWriteAccess;
    barrier.src.layout = tracker.layout;
    if (!is_image) barrier.dst.layout = barrier.src.layout = VK_IMAGE_LAYOUT_UNDEFINED;

    if (writes || layout_change) {
        // A layout transition is a write too: later readers wait for it through its dst stages.
        tracker.last_write = {next.stages, writes ? (next.access & kWriteAccess) : VK_ACCESS_2_NONE, next.layout};
        tracker.read_stages = writes ? 0 : next.stages;
        // After a write nothing has seen it yet, not even its own stage: a later read
        // in the same stage (another dispatch) still needs a barrier. After a
        // transition-only step the new layout's readers have been served.
        tracker.visible_stages = writes ? 0 : next.stages;
        tracker.visible_access = writes ? 0 : next.access;
        tracker.layout = next.layout;
        if (!layout_change && barrier.src.stages == VK_PIPELINE_STAGE_2_NONE) return std::nullopt;  // first use
        return barrier;
    }
    // A read in the current layout.
    const bool covered = (next.stages & ~tracker.visible_stages) == 0 && (next.access & ~tracker.visible_access) == 0;
    tracker.read_stages |= next.stages;
    if (covered || barrier.src.stages == VK_PIPELINE_STAGE_2_NONE) return std::nullopt;
    tracker.visible_stages |= next.stages;
    tracker.visible_access |= next.access;
    return barrier;
}

}  // namespace

BarrierPlan derive_barriers(const std::vector<ResourceTimeline>& timelines, size_t pass_count) {
    BarrierPlan plan;
    plan.before_pass.resize(pass_count);
    for (uint32_t resource = 0; resource < timelines.size(); ++resource) {
        const ResourceTimeline& timeline = timelines[resource];
        Tracker tracker;
        tracker.last_write = {timeline.initial.stages, timeline.initial.access & kWriteAccess, timeline.initial.layout};
        tracker.layout = timeline.initial.layout;
        for (const TimelineAccess& access : timeline.accesses) {
            if (auto barrier = step(tracker, access.state, access.writes, resource, timeline.is_image)) {
                plan.before_pass[access.position].push_back(*barrier);
            }
        }
        if (timeline.final_state) {
            const bool final_writes = (timeline.final_state->access & kWriteAccess) != 0;
            if (auto barrier = step(tracker, *timeline.final_state, final_writes, resource, timeline.is_image)) {
                plan.after_last_pass.push_back(*barrier);
            }
        }
    }
    return plan;
}

std::string describe(const Barrier& barrier, const std::vector<ResourceTimeline>& timelines) {
    std::string text = std::string(barrier.is_image ? "image '" : "buffer '") + timelines[barrier.resource].name +
                       "' " + stage_names(barrier.src.stages) + "/" + access_names(barrier.src.access) + " -> " +
                       stage_names(barrier.dst.stages) + "/" + access_names(barrier.dst.access);
    if (barrier.is_image) {
        text += ", " + std::string(layout_name(barrier.src.layout)) + " -> " + layout_name(barrier.dst.layout);
    }
    return text;
}

std::string dump_barriers(const BarrierPlan& plan, const std::vector<ResourceTimeline>& timelines,
                          const std::vector<std::string>& pass_names) {
    std::string text;
    for (size_t position = 0; position < plan.before_pass.size(); ++position) {
        for (const Barrier& barrier : plan.before_pass[position]) {
            text += "before '" + pass_names[position] + "': " + describe(barrier, timelines) + "\n";
        }
    }
    for (const Barrier& barrier : plan.after_last_pass) text += "after all: " + describe(barrier, timelines) + "\n";
    return text;
}

}  // namespace vkw::fg
