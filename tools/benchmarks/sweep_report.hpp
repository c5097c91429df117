// The output of `vkwater bench`: one row per quality setting (its time and its errors),
// written as CSV and as an SVG plot of error against time (log scales, one panel per
// metric, the Pareto front marked), with no dependency beyond the standard library.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

namespace vkw::bench {

struct SweepRow {
    std::string setting;     // e.g. "grid=512 caustics=on"
    double median_ms = 0.0;  // per frame
    double spread_ms = 0.0;  // interquartile range
    double rel_mse = 0.0, flip = 0.0, bias = 0.0;
};

// Indices of the rows no other row beats in both time and relMSE.
std::vector<size_t> pareto_front(const std::vector<SweepRow>& rows);

void write_csv(const std::filesystem::path& file, const std::vector<SweepRow>& rows);
void write_svg(const std::filesystem::path& file, const std::string& title, const std::vector<SweepRow>& rows);

}  // namespace vkw::bench
