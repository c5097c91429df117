// The corpus of bad scene files in tests/scene/bad/: each must be refused with a one-line
// vkw::UserError (never a crash or another exception) that names the file, the field and the
// accepted range. Every file in the folder must have a row here, so none is silently skipped.
#include <algorithm>
#include <set>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "engine/scene/scene_loader.hpp"
#include "scene_test_support.hpp"

namespace vkw {
namespace {

struct BadScene {
    const char* file;
    std::vector<std::string> expected;  // substrings of the message, after "<path>: "
};

// Printed as the test name suffix, so a failure says which file.
std::ostream& operator<<(std::ostream& out, const BadScene& bad) { return out << bad.file; }

const std::vector<BadScene> kBadScenes = {
    // Not JSON at all.
    {"empty.json", {"top level: empty (no JSON value) (accepted: a JSON object)"}},
    {"whitespace_only.json", {"top level: empty (no JSON value)"}},
    {"malformed_missing_comma.json", {"line 3, column 3: malformed JSON: syntax error while parsing object",
                                      "(accepted: JSON as in RFC 8259"}},
    {"malformed_trailing_comma.json", {"line 2, column 59: malformed JSON: syntax error", "expected string literal"}},
    {"comment.json", {"line 2, column 3: malformed JSON", "no comments"}},
    {"trailing_garbage.json", {"line 5, column 3: malformed JSON", "expected end of input"}},
    {"truncated.json", {"line 4, column 1: malformed JSON", "unexpected end of input"}},
    {"duplicate_key.json", {"camera.fov_y_deg: duplicate key (accepted: each key at most once per object)"}},
    {"huge_number.json", {"camera.far: 1e999 is not a finite number (line 2, column 66)",
                          "(accepted: numbers of magnitude below 1.8e308)"}},
    {"huge_number_in_array.json", {"sun.irradiance[1]: -1e400 is not a finite number (line 3, column 51)"}},
    {"nested_too_deeply.json", {"description[0][0]", "nested too deeply (accepted: at most 64 levels of objects and arrays)"}},
    {"nan_string.json", {"sun.elevation_deg: string \"nan\" is not a finite number",
                         "(accepted: -90 <= value <= 90 degrees)"}},
    // Wrong shape or type.
    {"top_level_array.json", {"top level: expected a JSON object, got array of 1 element [{"}},
    {"wrong_type_fov.json", {"camera.fov_y_deg: expected a number, got string \"wide\"",
                             "(accepted: 1 < value < 179 degrees)"}},
    {"wrong_type_section.json", {"sky: expected an object, got array of 3 elements [0.3,0.4,0.5]"}},
    {"vec3_two_elements.json", {"camera.position: expected an array of 3 numbers, got array of 2 elements [0,1]",
                                "(accepted: an array of 3 finite numbers, in m)"}},
    {"description_not_string.json", {"description: expected a string, got number 42"}},
    // Missing or unknown fields.
    {"missing_sky_radiance.json", {"sky.radiance: missing required field",
                                   "(accepted: an array of 3 numbers, each value >= 0 W m^-2 sr^-1)"}},
    {"missing_camera_target.json", {"camera.target: missing required field"}},
    {"no_sun.json", {"sun: missing required field (accepted: an object)"}},
    {"unknown_field_fovy.json", {"camera.fovy: unknown field (did you mean 'fov_y_deg'?)",
                                 "(accepted: position, target, fov_y_deg, near, far, exposure)"}},
    {"unknown_section_typo.json", {"camra: unknown field (did you mean 'camera'?)"}},
    {"unknown_sun_field_typo.json", {"sun.elevaton_deg: unknown field (did you mean 'elevation_deg'?)"}},
    // Out of range.
    {"fov_zero.json", {"camera.fov_y_deg: 0 is out of range (accepted: 1 < value < 179 degrees)"}},
    {"fov_180.json", {"camera.fov_y_deg: 180 is out of range (accepted: 1 < value < 179 degrees)"}},
    {"near_zero.json", {"camera.near: 0 is out of range (accepted: value > 0 m)"}},
    {"near_equals_far.json", {"camera.far: 10 is not greater than camera.near = 10 (accepted: value > camera.near)"}},
    {"near_beyond_default_far.json", {"camera.far: 500 (the default) is not greater than camera.near = 600"}},
    {"exposure_negative.json", {"camera.exposure: -1 is out of range (accepted: value > 0)"}},
    {"position_equals_target.json", {"camera.target: [0, 1, 3] coincides with camera.position",
                                     "(accepted: a point at least 1e-06 m from camera.position)"}},
    {"negative_irradiance.json", {"sun.irradiance[1]: -1 is out of range (accepted: value >= 0 W m^-2)"}},
    {"negative_sky_radiance.json", {"sky.radiance[0]: -0.3 is out of range (accepted: value >= 0 W m^-2 sr^-1)"}},
    {"albedo_above_one.json", {"floor.albedo[2]: 1.2 is out of range (accepted: 0 <= value <= 1)"}},
    {"half_extent_zero.json", {"floor.half_extent: 0 is out of range (accepted: value > 0 m)"}},
    {"sun_elevation_91.json", {"sun.elevation_deg: 91 is out of range (accepted: -90 <= value <= 90 degrees)"}},
    // The sun's two forms.
    {"both_sun_forms.json", {"sun: both direction and elevation_deg/azimuth_deg are given",
                             "(accepted: either direction, or elevation_deg with optional azimuth_deg)"}},
    {"neither_sun_form.json", {"sun: no direction given (accepted: either direction, or elevation_deg"}},
    {"azimuth_without_elevation.json", {"sun.elevation_deg: missing (azimuth_deg is given)"}},
    {"sun_direction_up.json", {"sun.direction: [0.2, 1, 0] does not point downward", "(accepted: a non-zero vector with y < 0"}},
    {"sun_direction_zero.json", {"sun.direction: [0, 0, 0] has no direction"}},
};

class scene_bad_file : public ::testing::TestWithParam<BadScene> {};

TEST_P(scene_bad_file, RefusedWithFieldAndRange) {
    const BadScene& bad = GetParam();
    const std::filesystem::path file = test::kSourceDir / "tests/scene/bad" / bad.file;
    ASSERT_TRUE(std::filesystem::exists(file)) << file;
    const std::string message = test::user_error_of([&] { load_scene(file); });
    EXPECT_EQ(message.find('\n'), std::string::npos) << "not one line: " << message;
    EXPECT_TRUE(message.starts_with(file.string() + ": ")) << message;
    for (const std::string& expected : bad.expected) {
        EXPECT_NE(message.find(expected), std::string::npos) << "expected '" << expected << "' in: " << message;
    }
}

INSTANTIATE_TEST_SUITE_P(scene, scene_bad_file, ::testing::ValuesIn(kBadScenes),
                         [](const ::testing::TestParamInfo<BadScene>& param) {
                             std::string name = std::filesystem::path(param.param.file).stem().string();
                             std::replace_if(name.begin(), name.end(), [](char c) { return !std::isalnum(c); }, '_');
                             return name;
                         });

TEST(scene_bad_corpus, EveryFileHasARowAndEveryRowAFile) {
    std::set<std::string> on_disk;
    for (const auto& entry : std::filesystem::directory_iterator(test::kSourceDir / "tests/scene/bad")) {
        on_disk.insert(entry.path().filename().string());
    }
    std::set<std::string> in_table;
    for (const BadScene& bad : kBadScenes) in_table.insert(bad.file);
    EXPECT_EQ(on_disk, in_table);
    EXPECT_GE(in_table.size(), 15u);
}

}  // namespace
}  // namespace vkw
