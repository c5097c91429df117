// The 2-thread C++ scatter of caustics_bench, for context: the same photons, taps and fixed-point
// quantities as shaders/caustics/bench/caustic_scatter_fixed.comp (R x R photons, 2 x 2 taps x RGB
// = 12 uint64 adds each, at the texels a flat-water photon of the same cell reaches), on the CPU.
#pragma once

#include "tools/benchmarks/caustic_scatter_passes.hpp"

#include <cstdint>

namespace vkwbench {

enum class CpuScatterMethod {
    PrivateBuffers,  // each thread adds into its own zeroed map, then both maps are summed
    SharedAtomics,   // both threads fetch_add (relaxed) into one shared map
};

struct CpuScatterResult {
    double ms = 0.0;        // the scatter and (PrivateBuffers) the reduction; not the zeroing
    uint64_t checksum = 0;  // the sum of every texel, so the work cannot be optimised away
};

// The photons, map and margins of `push` (scatter_push).
CpuScatterResult cpu_scatter(CpuScatterMethod method, const ScatterPush& push);

const char* cpu_scatter_name(CpuScatterMethod method);

}  // namespace vkwbench
