// sweep.csv, the table `vkwater bench` writes and `vkwater bench merge` reads back.
#pragma once

#include "tools/benchmarks/sweep_report.hpp"

#include <filesystem>
#include <vector>

namespace vkw::bench {

// Columns: setting, median_ms, spread_ms, rel_mse, flip, bias, rel_mse_<f>x, flip_<f>x (f =
// downsample_factor), caustic_rel_mse, inscatter_rel_mse ("n/a" when absent), memory_bytes,
// calibration_ms, median_cal and spread_cal (the times in calibration passes), device, index,
// settings. Text fields are quoted, a quote inside doubled (RFC 4180).
void write_csv(const std::filesystem::path& file, const std::vector<SweepRow>& rows, int downsample_factor);

struct SweepTable {
    std::vector<SweepRow> rows;
    int downsample_factor = 0;
};

// Reads what write_csv wrote. vkw::UserError naming the file, the line and the column for anything
// else (an older bench's columns, a field that is not a number, a row cut short).
SweepTable read_csv(const std::filesystem::path& file);

}  // namespace vkw::bench
