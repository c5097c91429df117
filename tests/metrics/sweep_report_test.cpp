// bench's report files: the CSV's columns (a missing caustic layer as "n/a") and reading it back,
// the Pareto front, an SVG that stays well-formed XML whatever the settings hold, and the merge of
// a sweep's shards.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "engine/core/errors.hpp"
#include "tools/benchmarks/sweep_csv.hpp"
#include "tools/benchmarks/sweep_merge.hpp"
#include "tools/benchmarks/sweep_report.hpp"

namespace vkw {
namespace {

namespace fs = std::filesystem;

std::string read_text(const fs::path& file) {
    std::ifstream in(file);
    std::stringstream text;
    text << in.rdbuf();
    return text.str();
}

// Two rows: the second is faster and more exact, so the first is dominated.
std::vector<bench::SweepRow> two_rows() {
    bench::SweepRow slow{"grid=8 a&b<c", 20.0, 1.0,  0.5, 0.25,  -0.125, 0.25, 0.125,
                         std::nullopt,   0.75, 4096, 0.5, "gpu", 0,      2};
    bench::SweepRow fast{"grid=16", 10.0,         2.0,  0.25, 0.125, 0.0625, 0.0625, 0.03125,
                         0.5,       std::nullopt, 8192, 0.25, "gpu", 1,      2};
    return {slow, fast};
}

TEST(metrics_sweep_report, CsvHasEveryColumnAndNaForAMissingLayer) {
    const fs::path file = fs::path(::testing::TempDir()) / "metrics_sweep_report.csv";
    bench::write_csv(file, two_rows(), 4);
    EXPECT_EQ(read_text(file),
              "setting,median_ms,spread_ms,rel_mse,flip,bias,rel_mse_4x,flip_4x,caustic_rel_mse,inscatter_rel_mse,"
              "memory_bytes,calibration_ms,median_cal,spread_cal,device,index,settings\n"
              "\"grid=8 a&b<c\",20,1,0.5,0.25,-0.125,0.25,0.125,n/a,0.75,4096,0.5,40,2,\"gpu\",0,2\n"
              "\"grid=16\",10,2,0.25,0.125,0.0625,0.0625,0.03125,0.5,n/a,8192,0.25,40,8,\"gpu\",1,2\n");
}

// What write_csv writes, read_csv reads back: every field, quotes and commas in text included
// (a setting may hold an array, a device name a comma). The values are exact in 6 digits.
TEST(metrics_sweep_report, CsvReadsBackWhatItWrote) {
    const fs::path file = fs::path(::testing::TempDir()) / "metrics_sweep_roundtrip.csv";
    std::vector<bench::SweepRow> rows = two_rows();
    rows[0].setting = "sun.irradiance=[1,2,3] say=\"x\"";
    rows[1].device = "llvmpipe (LLVM 15.0.6, 256 bits)";
    bench::write_csv(file, rows, 4);
    const bench::SweepTable table = bench::read_csv(file);
    EXPECT_EQ(table.downsample_factor, 4);
    ASSERT_EQ(table.rows.size(), 2u);
    for (size_t i = 0; i < 2; ++i) {
        const bench::SweepRow& a = rows[i];
        const bench::SweepRow& b = table.rows[i];
        EXPECT_EQ(a.setting, b.setting);
        EXPECT_EQ(a.device, b.device);
        EXPECT_EQ(
            std::tie(a.median_ms, a.spread_ms, a.rel_mse, a.flip, a.bias, a.rel_mse_downsampled, a.flip_downsampled,
                     a.caustic_rel_mse, a.inscatter_rel_mse, a.memory_bytes, a.calibration_ms, a.index, a.settings),
            std::tie(b.median_ms, b.spread_ms, b.rel_mse, b.flip, b.bias, b.rel_mse_downsampled, b.flip_downsampled,
                     b.caustic_rel_mse, b.inscatter_rel_mse, b.memory_bytes, b.calibration_ms, b.index, b.settings));
    }
}

// Anything but this bench's table is one line naming the file, the line and the column.
TEST(metrics_sweep_report, CsvRefusesWhatItDidNotWrite) {
    const fs::path file = fs::path(::testing::TempDir()) / "metrics_sweep_bad.csv";
    bench::write_csv(file, two_rows(), 4);
    const std::string good = read_text(file);
    const std::string header = good.substr(0, good.find('\n') + 1);
    const auto expect_refused = [&](const std::string& text, const std::string& needle) {
        std::ofstream(file) << text;
        try {
            bench::read_csv(file);
            ADD_FAILURE() << "accepted:\n" << text;
        } catch (const UserError& e) {
            EXPECT_NE(std::string(e.what()).find(needle), std::string::npos) << e.what();
        }
    };
    // An older bench's table: no calibration column.
    expect_refused(
        "setting,median_ms,spread_ms,rel_mse,flip,bias,rel_mse_4x,flip_4x,caustic_rel_mse,"
        "inscatter_rel_mse,memory_bytes\n",
        "line 1: not the columns of this vkwater's bench");
    expect_refused(header + "\"a\",x,1,0.5,0.25,-0.125,0.25,0.125,n/a,0.75,4096,0.5,40,2,\"gpu\",0,2\n",
                   "line 2, column median_ms: 'x' is not a finite number");
    expect_refused(header + "\"a\",1,1,0.5,0.25,-0.125,0.25,0.125,n/a,0.75,4096,0,40,2,\"gpu\",0,2\n",
                   "column calibration_ms: '0' is not above 0");
    expect_refused(header + "\"a\",1,1,0.5,0.25,-0.125,0.25,0.125,n/a,0.75,4096,0.5,40,2,\"gpu\",2,2\n",
                   "column index: '2' is not below the column settings (2)");
    expect_refused(header + "\"a\",1,1,0.5\n", "line 2: 4 fields where the header has 17");
    expect_refused(header + "\"a,1,1\n", "line 2: 1 fields where the header has 17");
    // Below lines of metadata, the lines are still counted from the file's first.
    expect_refused("# Measured here\n# and now\n" + header + "\"a\",1,1,0.5\n",
                   "line 4: 4 fields where the header has 17");
    expect_refused("# Measured here\nsetting,median_ms\n", "line 2: not the header of vkwater bench's sweep.csv");
}

// The committed sweeps begin with where their figures come from (docs/sweeps/run.sh writes it as
// `# Measured ...` lines): read_csv reads past them to the same rows.
TEST(metrics_sweep_report, CsvReadsPastItsMetadataLines) {
    const fs::path file = fs::path(::testing::TempDir()) / "metrics_sweep_metadata.csv";
    bench::write_csv(file, two_rows(), 4);
    const std::string plain = read_text(file);
    const bench::SweepTable without = bench::read_csv(file);
    std::ofstream(file) << "# Measured 2026-12-06 at abc1234 on llvmpipe, 2 CPUs; load average 1.0 before\n"
                           "# a second line\n"
                        << plain;
    const bench::SweepTable with = bench::read_csv(file);
    ASSERT_EQ(with.rows.size(), without.rows.size());
    EXPECT_EQ(with.downsample_factor, without.downsample_factor);
    for (size_t i = 0; i < with.rows.size(); ++i) {
        EXPECT_EQ(with.rows[i].setting, without.rows[i].setting);
        EXPECT_EQ(with.rows[i].median_ms, without.rows[i].median_ms);
        EXPECT_EQ(with.rows[i].rel_mse, without.rows[i].rel_mse);
    }
}

bench::SweepTable shard(std::vector<bench::SweepRow> rows) { return {std::move(rows), 4}; }

// Shards join in the sweep's order, each row's time scaled by the median calibration pass over its
// own: a shard that ran at half the speed (frame and calibration both twice as long) merges to the
// same times as one at full speed. Errors pass unchanged.
TEST(metrics_sweep_report, MergeJoinsShardsInCalibrationUnits) {
    std::vector<bench::SweepRow> rows = two_rows();  // calibration 0.5 and 0.25 ms
    bench::SweepRow third = rows[1];
    third.setting = "grid=32";
    third.median_ms = 30.0;  // a slow machine's: 2 x 15 ms over 2 x 0.5 ms
    third.spread_ms = 4.0;
    third.calibration_ms = 1.0;
    third.index = 2;
    for (bench::SweepRow& row : rows) row.settings = 3;
    third.settings = 3;
    const bench::MergedSweep merged =
        bench::merge_sweeps({{"b.csv", shard({third, rows[1]})}, {"a.csv", shard({rows[0]})}});
    ASSERT_EQ(merged.rows.size(), 3u);
    EXPECT_EQ(merged.calibration_ms, 0.5);  // the median of 0.5, 0.25, 1
    EXPECT_EQ(merged.rows[0].setting, "grid=8 a&b<c");
    EXPECT_EQ(merged.rows[1].setting, "grid=16");
    EXPECT_EQ(merged.rows[2].setting, "grid=32");
    EXPECT_EQ(merged.rows[0].median_ms, 20.0);  // 20 ms at 0.5 ms: unchanged
    EXPECT_EQ(merged.rows[1].median_ms, 20.0);  // 10 ms at 0.25 ms: 40 calibration passes
    EXPECT_EQ(merged.rows[1].spread_ms, 4.0);
    EXPECT_EQ(merged.rows[2].median_ms, 15.0);  // 30 ms at 1 ms: 30 calibration passes
    EXPECT_EQ(merged.rows[2].spread_ms, 2.0);
    EXPECT_EQ(merged.rows[1].rel_mse, rows[1].rel_mse);
    for (const bench::SweepRow& row : merged.rows) EXPECT_EQ(row.calibration_ms, 0.5);
}

TEST(metrics_sweep_report, MergeRefusesShardsThatAreNotOneSweep) {
    const std::vector<bench::SweepRow> rows = two_rows();
    const auto expect_refused = [](const std::vector<std::pair<fs::path, bench::SweepTable>>& shards,
                                   const std::string& needle) {
        try {
            bench::merge_sweeps(shards);
            ADD_FAILURE() << "merged";
        } catch (const UserError& e) {
            EXPECT_NE(std::string(e.what()).find(needle), std::string::npos) << e.what();
        }
    };
    bench::SweepRow other_device = rows[1];
    other_device.device = "cpu";
    expect_refused({{"a.csv", shard({rows[0]})}, {"b.csv", shard({other_device})}},
                   "'b.csv': device 'cpu', 'a.csv': 'gpu': times of different devices do not compare");
    expect_refused({{"a.csv", shard({rows[0]})}, {"b.csv", shard({rows[0]})}},
                   "setting 0 ('grid=8 a&b<c') is in both 'a.csv' and 'b.csv'");
    expect_refused({{"a.csv", shard({rows[0]})}}, "the shards hold 1 of the sweep's 2 settings; missing: 1");
    bench::SweepRow longer = rows[1];
    longer.settings = 3;
    expect_refused({{"a.csv", shard({rows[0]})}, {"b.csv", shard({longer})}}, "a sweep of 3 settings");
    expect_refused({{"a.csv", shard({rows[0]})}, {"b.csv", {{rows[1]}, 2}}}, "errors at 2x");
    // A task with no setting (more tasks than settings) merges as nothing.
    EXPECT_EQ(bench::merge_sweeps({{"a.csv", shard({rows[0]})}, {"b.csv", shard({})}, {"c.csv", shard({rows[1]})}})
                  .rows.size(),
              2u);
}

TEST(metrics_sweep_report, ParetoFrontLeavesOutDominatedRows) {
    EXPECT_EQ(bench::pareto_front(two_rows()), std::vector<size_t>{1});
}

TEST(metrics_sweep_report, SvgEscapesTextAndAddsTheLayerPanelsWhenSomeRowHasThem) {
    const fs::path file = fs::path(::testing::TempDir()) / "metrics_sweep_report.svg";
    bench::write_svg(file, "scene <1> & co", two_rows(), 4);
    const std::string svg = read_text(file);
    EXPECT_NE(svg.find("scene &lt;1&gt; &amp; co"), std::string::npos) << svg;
    EXPECT_NE(svg.find("1. grid=8 a&amp;b&lt;c"), std::string::npos) << svg;
    EXPECT_EQ(svg.find("a&b"), std::string::npos) << svg;
    EXPECT_NE(svg.find("relMSE of the caustic layer"), std::string::npos) << svg;
    EXPECT_NE(svg.find("relMSE of the in-scatter layer"), std::string::npos) << svg;
    std::vector<bench::SweepRow> without_layer = two_rows();
    without_layer[1].caustic_rel_mse.reset();
    without_layer[0].inscatter_rel_mse.reset();
    bench::write_svg(file, "scene", without_layer, 4);
    EXPECT_EQ(read_text(file).find("relMSE of the caustic layer"), std::string::npos);
    EXPECT_EQ(read_text(file).find("relMSE of the in-scatter layer"), std::string::npos);
}

}  // namespace
}  // namespace vkw
