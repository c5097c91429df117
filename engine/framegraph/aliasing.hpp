// Transient memory aliasing: resources whose lifetimes (first..last pass in execution
// order) do not overlap may share memory. A pure function, tested without a GPU.
#pragma once

#include <cstdint>
#include <vector>

namespace vkw::fg {

struct AliasRequest {
    uint64_t size = 0;
    uint64_t alignment = 1;
    uint32_t first_use = 0;  // execution position of the first pass that uses it
    uint32_t last_use = 0;   // ...and of the last
};

struct AliasPlan {
    std::vector<uint64_t> offsets;  // per request, in one shared heap
    uint64_t heap_size = 0;         // bytes with aliasing (peak)
    uint64_t unaliased_size = 0;    // bytes if every resource had its own memory (alignment included)
    // For each request, the earlier requests whose memory it reuses: its first use
    // must wait for their last use.
    std::vector<std::vector<uint32_t>> predecessors;

    bool operator==(const AliasPlan&) const = default;
};

// Greedy placement, largest first: each resource goes to the lowest aligned offset
// that does not overlap any already placed resource whose lifetime overlaps its own.
AliasPlan plan_aliasing(const std::vector<AliasRequest>& requests);

}  // namespace vkw::fg
