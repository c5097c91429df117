// The committed sweeps (docs/sweeps/<scene>.csv, written by docs/sweeps/run.sh) rank settings
// by their relMSE against the committed references (tests/references/). The ranking means
// something only where the reference's own error is well below every setting's: each
// reference's estimated error (manifest.json) must be below a tenth of the smallest relMSE in
// its scene's sweep. GPU-free: it reads the two files.
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <sstream>
#include <string>
#include <vector>

namespace vkw {
namespace {

const std::filesystem::path kSource = VKWATER_SOURCE_DIR;

// The references are stored as 32-bit float EXR, so no reference is closer to the model than
// that rounding: each value b is stored as b (1 + d) with |d| <= 2^-24, and with the rounding
// error spread evenly over [-ulp/2, ulp/2] within a binade (ulp <= 2^-23 b), E[d^2] <= 2^-48 / 3.
// A relMSE term is (b d)^2 / (b^2 + 0.01) <= d^2, so storage adds at most 2^-48 / 3 = 1.2e-15
// to a relMSE (a mean over 360,000 values: their average is the expectation). Estimates below
// that (the closed-form scenes' 1e-18: double-precision evaluation) count as this floor: a
// reference exact to rounding is held to the rounding of its file.
const double kFp32StorageRelMse = std::ldexp(1.0, -48) / 3.0;

// The smallest value of the rel_mse column.
double smallest_rel_mse(const std::filesystem::path& csv_file) {
    std::ifstream csv(csv_file);
    EXPECT_TRUE(csv) << "cannot read " << csv_file << " (regenerate it with docs/sweeps/run.sh)";
    std::string line;
    while (std::getline(csv, line) && line.rfind('#', 0) == 0) {
        // where the figures come from (docs/sweeps/run.sh), before the header
    }
    std::vector<std::string> header;
    for (std::stringstream columns(line); std::getline(columns, line, ',');) header.push_back(line);
    const auto column = std::find(header.begin(), header.end(), "rel_mse");
    EXPECT_NE(column, header.end()) << csv_file << " has no rel_mse column";
    const auto index = static_cast<size_t>(column - header.begin());
    double smallest = std::numeric_limits<double>::infinity();
    while (std::getline(csv, line)) {
        // The setting (first column) is quoted and holds no comma.
        std::vector<std::string> fields;
        for (std::stringstream columns(line); std::getline(columns, line, ',');) fields.push_back(line);
        EXPECT_GT(fields.size(), index) << csv_file;
        if (fields.size() > index) smallest = std::min(smallest, std::stod(fields[index]));
    }
    return smallest;
}

void expect_reference_a_tenth_of_the_sweep(const std::string& scene) {
    std::ifstream manifest_file(kSource / "tests/references/manifest.json");
    const nlohmann::json manifest = nlohmann::json::parse(manifest_file);
    const double estimate = manifest.at(scene + ".json").at("estimated_rel_mse").get<double>();
    const double reference_error = std::max(estimate, kFp32StorageRelMse);
    const double smallest = smallest_rel_mse(kSource / "docs/sweeps" / (scene + ".csv"));
    EXPECT_LT(reference_error, 0.1 * smallest)
        << scene << ": the reference's estimated error " << estimate << " (counted as " << reference_error
        << ") is not below a tenth of the sweep's smallest relMSE " << smallest
        << ": the sweep's ranking of its best settings is within the reference's own error. Regenerate the "
           "reference at a higher quality (tools/reference), then the sweep (docs/sweeps/run.sh).";
}

TEST(metrics_committed_sweeps, CalmReferenceIsATenthOfTheSweepsSmallestError) {
    expect_reference_a_tenth_of_the_sweep("calm");
}

TEST(metrics_committed_sweeps, PoolReferenceIsATenthOfTheSweepsSmallestError) {
    expect_reference_a_tenth_of_the_sweep("pool");
}

// lake.exr is rendered at 64 surface cells per shortest wavelength (vkwater reference
// --cells-per-wavelength 64): its meshes' caustics change 2.5% RMS from M/2 to M cells, an
// estimate of 6.4e-4 (at 32 cells it was 0.010, above a tenth of the sweep).
TEST(metrics_committed_sweeps, LakeReferenceIsATenthOfTheSweepsSmallestError) {
    expect_reference_a_tenth_of_the_sweep("lake");
}

}  // namespace
}  // namespace vkw
