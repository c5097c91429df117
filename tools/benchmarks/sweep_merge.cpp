#include "tools/benchmarks/sweep_merge.hpp"

#include "engine/core/errors.hpp"
#include "engine/image/file_paths.hpp"

#include <algorithm>
#include <map>

namespace vkw::bench {

MergedSweep merge_sweeps(const std::vector<std::pair<std::filesystem::path, SweepTable>>& shards) {
    MergedSweep merged;
    std::map<size_t, std::pair<SweepRow, std::filesystem::path>> by_index;
    const std::filesystem::path* first_file = nullptr;
    size_t settings = 0;
    for (const auto& [file, table] : shards) {
        if (table.rows.empty()) continue;  // a task of an array with more tasks than settings
        if (!first_file) {
            first_file = &file;
            merged.downsample_factor = table.downsample_factor;
            merged.device = table.rows.front().device;
            settings = table.rows.front().settings;
        }
        if (table.downsample_factor != merged.downsample_factor) {
            throw UserError(quoted_path(file) + ": errors at " + std::to_string(table.downsample_factor) + "x, " +
                            quoted_path(*first_file) + ": at " + std::to_string(merged.downsample_factor) +
                            "x: not shards of one sweep");
        }
        for (const SweepRow& row : table.rows) {
            if (row.device != merged.device) {
                throw UserError(quoted_path(file) + ": device '" + row.device + "', " + quoted_path(*first_file) +
                                ": '" + merged.device +
                                "': times of different devices do not compare; merge each device's shards on their "
                                "own");
            }
            if (row.settings != settings) {
                throw UserError(quoted_path(file) + ": a sweep of " + std::to_string(row.settings) + " settings, " +
                                quoted_path(*first_file) + ": of " + std::to_string(settings) +
                                ": not shards of one sweep");
            }
            const auto [at, inserted] = by_index.emplace(row.index, std::make_pair(row, file));
            if (!inserted) {
                throw UserError("setting " + std::to_string(row.index) + " ('" + row.setting + "') is in both " +
                                quoted_path(at->second.second) + " and " + quoted_path(file) +
                                ": give each shard once");
            }
        }
    }
    if (!first_file) throw UserError("bench merge: no shard to merge");
    if (by_index.size() != settings) {
        std::string missing;
        size_t listed = 0;
        for (size_t index = 0; index < settings && listed < 10; ++index) {
            if (by_index.count(index)) continue;
            missing += (listed++ ? ", " : "") + std::to_string(index);
        }
        throw UserError("the shards hold " + std::to_string(by_index.size()) + " of the sweep's " +
                        std::to_string(settings) + " settings; missing: " + missing +
                        (settings - by_index.size() > listed ? ", ..." : "") +
                        " (0-based; bench --shard I/N renders the settings whose index is I modulo N)");
    }
    std::vector<double> calibrations;
    for (const auto& [index, entry] : by_index) calibrations.push_back(entry.first.calibration_ms);
    std::nth_element(calibrations.begin(), calibrations.begin() + calibrations.size() / 2, calibrations.end());
    merged.calibration_ms = calibrations[calibrations.size() / 2];
    for (const auto& [index, entry] : by_index) {
        SweepRow row = entry.first;
        const double scale = merged.calibration_ms / row.calibration_ms;
        row.median_ms *= scale;
        row.spread_ms *= scale;
        row.calibration_ms = merged.calibration_ms;
        merged.rows.push_back(std::move(row));
    }
    return merged;
}

}  // namespace vkw::bench
