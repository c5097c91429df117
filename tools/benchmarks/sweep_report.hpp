// The output of `vkwater bench`: one row per quality setting (its time, its errors and its
// memory), written as CSV (sweep_csv.hpp) and as an SVG plot of error against time (log scales, one
// panel per metric, the Pareto front marked), with no dependency beyond the standard library.
#pragma once

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace vkw::bench {

struct SweepRow {
    std::string setting;     // e.g. "grid=512 caustics=on"
    double median_ms = 0.0;  // per frame
    double spread_ms = 0.0;  // interquartile range
    double rel_mse = 0.0, flip = 0.0, bias = 0.0;
    // The same two metrics with both images box-downsampled (by the report's factor).
    double rel_mse_downsampled = 0.0, flip_downsampled = 0.0;
    std::optional<double> caustic_rel_mse;    // empty when an image has no caustic layer
    std::optional<double> inscatter_rel_mse;  // empty when an image has no in-scatter layer
    uint64_t memory_bytes = 0;                // the frame's transient heap plus imported resources
    // The calibration pass's median time in the same frames (passes/common/calibration.hpp): the
    // unit that makes times from different runs of one device comparable (sweep_merge.hpp).
    double calibration_ms = 0.0;
    std::string device;   // the Vulkan device's name
    size_t index = 0;     // the setting's position in the whole sweep, 0-based
    size_t settings = 0;  // how many settings the whole sweep has (a shard renders some)
};

// Indices of the rows no other row beats in both time and relMSE.
std::vector<size_t> pareto_front(const std::vector<SweepRow>& rows);

// Panels: relMSE, relMSE at <f>x, FLIP, |bias|, and the caustic and in-scatter layers' relMSE when
// some row has them. Points are numbered by row; the legend below names each row's setting.
void write_svg(const std::filesystem::path& file, const std::string& title, const std::vector<SweepRow>& rows,
               int downsample_factor);

}  // namespace vkw::bench
