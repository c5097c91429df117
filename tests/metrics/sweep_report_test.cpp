// bench's report files: the CSV's columns (a missing caustic layer as "n/a"), the Pareto
// front, and an SVG that stays well-formed XML whatever the settings hold.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

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
    bench::SweepRow slow{"grid=8 a&b<c", 20.0, 1.0, 0.5, 0.25, -0.125, 0.25, 0.125, std::nullopt, 0.75, 4096};
    bench::SweepRow fast{"grid=16", 10.0, 2.0, 0.25, 0.125, 0.0625, 0.0625, 0.03125, 0.5, std::nullopt, 8192};
    return {slow, fast};
}

TEST(metrics_sweep_report, CsvHasEveryColumnAndNaForAMissingLayer) {
    const fs::path file = fs::path(::testing::TempDir()) / "metrics_sweep_report.csv";
    bench::write_csv(file, two_rows(), 4);
    EXPECT_EQ(read_text(file),
              "setting,median_ms,spread_ms,rel_mse,flip,bias,rel_mse_4x,flip_4x,caustic_rel_mse,inscatter_rel_mse,"
              "memory_bytes\n"
              "\"grid=8 a&b<c\",20,1,0.5,0.25,-0.125,0.25,0.125,n/a,0.75,4096\n"
              "\"grid=16\",10,2,0.25,0.125,0.0625,0.0625,0.03125,0.5,n/a,8192\n");
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
