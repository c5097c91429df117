// vkwater bench merge: the sweep.csv of a sweep's shards (bench --shard I/N, each perhaps on
// another machine of a cluster) joined into the one table a single run would have written.
#pragma once

#include "tools/benchmarks/sweep_csv.hpp"

#include <filesystem>
#include <string>
#include <utility>
#include <vector>

namespace vkw::bench {

struct MergedSweep {
    std::vector<SweepRow> rows;  // in the sweep's order
    int downsample_factor = 0;
    double calibration_ms = 0.0;  // the median of every row's calibration pass
    std::string device;
};

// Each row's times become calibration units (its time over its own calibration pass, measured in
// the same frames), scaled back to milliseconds by the median calibration pass of all rows: shards
// that ran at different loads, or on different machines with the same device, then compare, since
// the load and the clock speed slow the calibration pass as they slow the frame. Errors merge as
// they are (they depend on the device, not its load). vkw::UserError, naming the files, for
// shards of different devices (their times do not compare in any unit), of different sweeps
// (another number of settings or downsampling factor), a setting twice, or settings missing.
MergedSweep merge_sweeps(const std::vector<std::pair<std::filesystem::path, SweepTable>>& shards);

}  // namespace vkw::bench
