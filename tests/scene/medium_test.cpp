// The medium: presets give exactly the values of docs/model.md section 1's table (typed in here
// again from the document, not taken from the code's table), explicit coefficients, and the
// exclusive forms.
#include <gtest/gtest.h>

#include "engine/scene/scene_loader.hpp"
#include "tests/scene/scene_test_support.hpp"

namespace vkw {
namespace {

Scene with_medium(const std::string& medium_json) {
    const std::string text = R"({ "camera": { "position": [0, 1, 3], "target": [0, 0, 0] },
                                  "sun": { "elevation_deg": 45 }, "sky": { "radiance": [1, 1, 1] },
                                  "medium": )" +
                             medium_json + "}";
    return parse_scene(text, "medium.json");
}

std::string error_of(const std::string& medium_json) {
    return test::user_error_of([&] { with_medium(medium_json); });
}

struct TableRow {
    const char* name;
    glm::dvec3 sigma_a, sigma_s;
    double g;
};

TEST(scene_medium, PresetsAreExactlyThePhysicsTable) {
    const std::vector<TableRow> table = {
        {"pure", {1.169, 0.0638, 0.0150}, {0.0006, 0.0019, 0.0045}, 0.0},
        {"clear-ocean", {1.169, 0.0638, 0.0150}, {0.028, 0.035, 0.039}, 0.9},
        {"coastal", {1.169, 0.0638, 0.0150}, {0.17, 0.20, 0.234}, 0.9},
        {"turbid-harbour", {1.169, 0.0638, 0.0150}, {0.71, 0.82, 0.96}, 0.9},
    };
    for (const TableRow& row : table) {
        SCOPED_TRACE(row.name);
        const Medium medium = with_medium(std::string(R"({ "preset": ")") + row.name + "\" }").medium;
        EXPECT_EQ(medium.preset, row.name);
        EXPECT_EQ(medium.sigma_a, row.sigma_a);
        EXPECT_EQ(medium.sigma_s, row.sigma_s);
        EXPECT_EQ(medium.g, row.g);
        EXPECT_EQ(medium.sigma_t(), row.sigma_a + row.sigma_s);
    }
    EXPECT_EQ(medium_preset_names().size(), table.size());
}

TEST(scene_medium, DefaultIsPure) {
    const Medium absent = parse_scene(test::kMinimalScene, "min.json").medium;
    const Medium empty = with_medium("{}").medium;
    const Medium pure = with_medium(R"({ "preset": "pure" })").medium;
    for (const Medium& medium : {absent, empty}) {
        EXPECT_EQ(medium.preset, "pure");
        EXPECT_EQ(medium.sigma_a, pure.sigma_a);
        EXPECT_EQ(medium.sigma_s, pure.sigma_s);
        EXPECT_EQ(medium.g, pure.g);
    }
}

TEST(scene_medium, ExplicitCoefficients) {
    const Medium medium =
        with_medium(R"({ "sigma_a": [0.5, 0.1, 0.05], "sigma_s": [0.2, 0.3, 0.4], "g": -0.3 })").medium;
    EXPECT_EQ(medium.preset, "");
    EXPECT_EQ(medium.sigma_a, glm::dvec3(0.5, 0.1, 0.05));
    EXPECT_EQ(medium.sigma_s, glm::dvec3(0.2, 0.3, 0.4));
    EXPECT_EQ(medium.g, -0.3);
    EXPECT_EQ(with_medium(R"({ "sigma_a": [0, 0, 0], "sigma_s": [0, 0, 0] })").medium.g, 0.0);  // g defaults to 0
}

TEST(scene_medium, PresetPlusExplicitIsRefused) {
    for (const char* json : {R"({ "preset": "coastal", "sigma_a": [1, 1, 1] })", R"({ "preset": "pure", "g": 0.5 })"}) {
        const std::string message = error_of(json);
        EXPECT_NE(message.find("medium.json: medium: both preset and sigma_a/sigma_s/g are given"), std::string::npos)
            << message;
        EXPECT_NE(message.find("(accepted: either preset (one of pure, clear-ocean, coastal, turbid-harbour), or "
                               "sigma_a and sigma_s with optional g)"),
                  std::string::npos)
            << message;
    }
}

TEST(scene_medium, PartialCoefficientsAreRefused) {
    EXPECT_NE(error_of(R"({ "sigma_a": [1, 1, 1] })").find("medium.sigma_s: missing (sigma_a is given)"),
              std::string::npos);
    EXPECT_NE(error_of(R"({ "g": 0.5 })").find("medium.sigma_a: missing (sigma_s or g is given)"), std::string::npos);
}

TEST(scene_medium, UnknownPresetGetsAHint) {
    const std::string message = error_of(R"({ "preset": "turbid-harbor" })");
    EXPECT_NE(message.find("medium.preset: unknown value \"turbid-harbor\" (did you mean 'turbid-harbour'?)"),
              std::string::npos)
        << message;
}

}  // namespace
}  // namespace vkw
