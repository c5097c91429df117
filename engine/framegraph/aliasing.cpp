#include "engine/framegraph/aliasing.hpp"

#include <algorithm>
#include <numeric>

namespace vkw::fg {
namespace {

uint64_t align_up(uint64_t value, uint64_t alignment) {
    return alignment <= 1 ? value : (value + alignment - 1) / alignment * alignment;
}

bool lifetimes_overlap(const AliasRequest& a, const AliasRequest& b) {
    return a.first_use <= b.last_use && b.first_use <= a.last_use;
}

bool ranges_overlap(uint64_t a, uint64_t a_size, uint64_t b, uint64_t b_size) {
    return a < b + b_size && b < a + a_size;
}

}  // namespace

AliasPlan plan_aliasing(const std::vector<AliasRequest>& requests) {
    AliasPlan plan;
    plan.offsets.assign(requests.size(), 0);
    plan.predecessors.resize(requests.size());
    std::vector<uint32_t> order(requests.size());
    std::iota(order.begin(), order.end(), 0u);
    std::stable_sort(order.begin(), order.end(),
                     [&](uint32_t a, uint32_t b) { return requests[a].size > requests[b].size; });

    std::vector<uint32_t> placed;
    for (uint32_t index : order) {
        const AliasRequest& request = requests[index];
        plan.unaliased_size = align_up(plan.unaliased_size, request.alignment) + request.size;
        // Candidate offsets: 0 and the end of every conflicting placed resource.
        std::vector<uint64_t> candidates{0};
        for (uint32_t other : placed) {
            if (lifetimes_overlap(request, requests[other])) {
                candidates.push_back(align_up(plan.offsets[other] + requests[other].size, request.alignment));
            }
        }
        std::sort(candidates.begin(), candidates.end());
        for (uint64_t offset : candidates) {
            const bool fits = std::none_of(placed.begin(), placed.end(), [&](uint32_t other) {
                return lifetimes_overlap(request, requests[other]) &&
                       ranges_overlap(offset, request.size, plan.offsets[other], requests[other].size);
            });
            if (fits) {
                plan.offsets[index] = offset;
                break;
            }
        }
        plan.heap_size = std::max(plan.heap_size, plan.offsets[index] + request.size);
        placed.push_back(index);
    }
    // Memory reuse: an earlier-lifetime resource whose range overlaps.
    for (uint32_t a = 0; a < requests.size(); ++a) {
        for (uint32_t b = 0; b < requests.size(); ++b) {
            if (a != b && requests[b].last_use < requests[a].first_use &&
                ranges_overlap(plan.offsets[a], requests[a].size, plan.offsets[b], requests[b].size)) {
                plan.predecessors[a].push_back(b);
            }
        }
    }
    return plan;
}

}  // namespace vkw::fg
