// The corpus of bad scene files in tests/scene/bad/: each must be refused with a one-line
// vkw::UserError (never a crash or another exception) that names the file, the field and the
// accepted range. Every file in the folder must have a row here, so none is silently skipped.
#include <algorithm>
#include <set>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "engine/scene/scene_loader.hpp"
#include "tests/scene/scene_test_support.hpp"

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
    {"malformed_missing_comma.json",
     {"line 3, column 3: malformed JSON: syntax error while parsing object", "(accepted: JSON as in RFC 8259"}},
    {"malformed_trailing_comma.json", {"line 2, column 59: malformed JSON: syntax error", "expected string literal"}},
    {"comment.json", {"line 2, column 3: malformed JSON", "no comments"}},
    {"trailing_garbage.json", {"line 5, column 3: malformed JSON", "expected end of input"}},
    {"truncated.json", {"line 4, column 1: malformed JSON", "unexpected end of input"}},
    {"duplicate_key.json", {"camera.fov_y_deg: duplicate key (accepted: each key at most once per object)"}},
    {"huge_number.json",
     {"camera.far: 1e999 is not a finite number (line 2, column 66)",
      "(accepted: numbers of magnitude below 1.8e308)"}},
    {"huge_number_in_array.json", {"sun.irradiance[1]: -1e400 is not a finite number (line 3, column 51)"}},
    {"nested_too_deeply.json",
     {"description[0][0]", "nested too deeply (accepted: at most 64 levels of objects and arrays)"}},
    {"nan_string.json",
     {"sun.elevation_deg: string \"nan\" is not a finite number", "(accepted: -90 <= value <= 90 degrees)"}},
    // Wrong shape or type.
    {"top_level_array.json", {"top level: expected a JSON object, got array of 1 element [{"}},
    {"wrong_type_fov.json",
     {"camera.fov_y_deg: expected a number, got string \"wide\"", "(accepted: 1 < value < 179 degrees)"}},
    {"wrong_type_section.json", {"sky: expected an object, got array of 3 elements [0.3,0.4,0.5]"}},
    {"vec3_two_elements.json",
     {"camera.position: expected an array of 3 numbers, got array of 2 elements [0,1]",
      "(accepted: an array of 3 numbers, each -1e+05 <= value <= 1e+05 m)"}},
    {"description_not_string.json", {"description: expected a string, got number 42"}},
    // Missing or unknown fields.
    {"missing_sky_radiance.json",
     {"sky.radiance: missing required field",
      "(accepted: an array of 3 numbers, each 0 <= value <= 1e+30 W m^-2 sr^-1)"}},
    {"missing_camera_target.json", {"camera.target: missing required field"}},
    {"no_sun.json", {"sun: missing required field (accepted: an object)"}},
    {"unknown_field_fovy.json",
     {"camera.fovy: unknown field (did you mean 'fov_y_deg'?)",
      "(accepted: position, target, direction, fov_y_deg, near, far, exposure)"}},
    {"unknown_section_typo.json", {"camra: unknown field (did you mean 'camera'?)"}},
    {"unknown_sun_field_typo.json", {"sun.elevaton_deg: unknown field (did you mean 'elevation_deg'?)"}},
    // Out of range.
    {"fov_zero.json", {"camera.fov_y_deg: 0 is out of range (accepted: 1 < value < 179 degrees)"}},
    {"fov_180.json", {"camera.fov_y_deg: 180 is out of range (accepted: 1 < value < 179 degrees)"}},
    {"near_zero.json", {"camera.near: 0 is out of range (accepted: 0 < value <= 1e+05 m)"}},
    {"near_equals_far.json", {"camera.far: 10 is not greater than camera.near = 10 (accepted: value > camera.near)"}},
    {"near_beyond_default_far.json", {"camera.far: 500 (the default) is not greater than camera.near = 600"}},
    {"exposure_negative.json", {"camera.exposure: -1 is out of range (accepted: 0 < value <= 1e+30)"}},
    {"position_equals_target.json",
     {"camera.target: [0, 1, 3] coincides with camera.position",
      "(accepted: a point at least 1e-06 m from camera.position)"}},
    {"negative_irradiance.json", {"sun.irradiance[1]: -1 is out of range (accepted: 0 <= value <= 1e+30 W m^-2)"}},
    {"sun_shadow_texels_too_large.json",
     {"sun.shadow_texels: 16384 is out of range", "(accepted: an integer, 16 <= value <= 8192 texels per side)"}},
    {"sun_shadow_texels_fraction.json", {"sun.shadow_texels: 512.5", "(accepted: an integer, 16 <= value <= 8192"}},
    {"negative_sky_radiance.json",
     {"sky.radiance[0]: -0.3 is out of range (accepted: 0 <= value <= 1e+30 W m^-2 sr^-1)"}},
    {"albedo_above_one.json", {"floor.albedo[2]: 1.2 is out of range (accepted: 0 <= value <= 1)"}},
    {"half_extent_zero.json", {"floor.half_extent: 0 is out of range (accepted: 0 < value <= 1e+05 m)"}},
    {"sun_elevation_91.json", {"sun.elevation_deg: 91 is out of range (accepted: -90 <= value <= 90 degrees)"}},
    // The sun's two forms.
    {"both_sun_forms.json",
     {"sun: both direction and elevation_deg/azimuth_deg are given",
      "(accepted: either direction, or elevation_deg with optional azimuth_deg)"}},
    {"neither_sun_form.json", {"sun: no direction given (accepted: either direction, or elevation_deg"}},
    {"azimuth_without_elevation.json", {"sun.elevation_deg: missing (azimuth_deg is given)"}},
    {"sun_direction_up.json",
     {"sun.direction: [0.2, 1, 0] does not point downward", "(accepted: a non-zero vector with y < 0"}},
    {"sun_direction_zero.json", {"sun.direction: [0, 0, 0] has no direction"}},
    // Water.
    {"water_ior_0_9.json", {"water.ior: 0.9 is out of range (accepted: 1 <= value <= 2)"}},
    {"water_ior_2_5.json", {"water.ior: 2.5 is out of range (accepted: 1 <= value <= 2)"}},
    {"water_ior_nan_string.json", {"water.ior: string \"NaN\" is not a finite number (accepted: 1 <= value <= 2)"}},
    {"water_unknown_field_typo.json",
     {"water.iro: unknown field (did you mean 'ior'?)",
      "(accepted: level, ior, half_extent, grid_resolution, mesh_resolution, mesh_cell_pixels, time, depth, seed, "
      "waves)"}},
    {"water_wrong_type.json", {"water: expected an object, got boolean true"}},
    {"water_grid_resolution_zero.json",
     {"water.grid_resolution: 0 is out of range", "(accepted: an integer, 2 <= value <= 4096 cells per side)"}},
    {"water_mesh_resolution_and_cell_pixels.json",
     {"water: both mesh_resolution and mesh_cell_pixels are given",
      "(accepted: at most one of mesh_resolution (a uniform mesh), mesh_cell_pixels (the screen's))"}},
    {"water_half_extent_word.json",
     {"water.half_extent: expected a number or \"infinite\", got string \"endless\"",
      "(accepted: 0 < value <= 1e+05 m, or \"infinite\")"}},
    {"water_half_extent_zero.json",
     {"water.half_extent: 0 is out of range (accepted: 0 < value <= 1e+05 m, or \"infinite\")"}},
    {"water_infinite_uniform_mesh.json",
     {"water.mesh_resolution: a uniform mesh over a square cannot cover infinite water",
      "(accepted: leave it out (infinite water is drawn from the screen's grid, mesh_cell_pixels), or give "
      "half_extent a number)"}},
    {"water_mesh_cell_pixels_zero.json",
     {"water.mesh_cell_pixels: 0 is out of range", "(accepted: an integer, 1 <= value <= 64 pixels)"}},
    {"water_grid_resolution_5000.json",
     {"water.grid_resolution: 5000 is out of range", "(accepted: an integer, 2 <= value <= 4096 cells per side)"}},
    {"water_grid_resolution_fraction.json",
     {"water.grid_resolution: 256.5 is not an integer", "(accepted: an integer, 2 <= value <= 4096 cells per side)"}},
    {"water_seed_negative.json",
     {"water.seed: -1 is out of range (accepted: an integer, 0 <= value <= 9007199254740991)"}},
    {"water_depth_zero.json", {"water.depth: 0 is out of range (accepted: 0 < value <= 1e+05 m)"}},
    {"water_below_floor.json",
     {"water.level: -2 is not above floor.height = -1.5, so the water has no volume",
      "(accepted: value > floor.height, or water.depth to give the volume its own bottom)"}},
    // Waves.
    {"wave_model_unknown.json", {"water.waves.model: unknown value \"gerstner\" (accepted: one of flat, sum, fft)"}},
    {"fft_resolution_100.json",
     {"water.waves.resolution: 100 is not a power of two", "(accepted: a power of two, 16 <= value <= 1024)"}},
    {"fft_resolution_2048.json",
     {"water.waves.resolution: 2048 is out of range (accepted: an integer, 16 <= value <= 1024)"}},
    {"fft_fetch_with_phillips.json",
     {"water.waves.fetch: is only used by the jonswap spectrum", "(accepted: fetch only with spectrum: jonswap)"}},
    {"steepness_sum_above_one.json",
     {"water.waves.components: the Gerstner steepness values sum to 1.5, so the surface folds",
      "(accepted: sum of steepness <= 1, or allow_folding: true)"}},
    {"wave_steepness_above_one.json",
     {"water.waves.components[0].steepness: 1.5 is out of range (accepted: 0 <= value <= 1)"}},
    {"wave_amplitude_negative.json",
     {"water.waves.components[0].amplitude: -0.01 is out of range (accepted: 0 <= value <= 1e+05 m)"}},
    {"wave_wavelength_zero.json",
     {"water.waves.components[0].wavelength: 0 is out of range (accepted: 0 < value <= 1e+05 m)"}},
    {"wave_speed_zero.json", {"water.waves.components[0].speed: 0 is out of range (accepted: 0 < value <= 1e+05 m/s)"}},
    {"allow_folding_not_bool.json", {"water.waves.allow_folding: expected true or false, got string \"yes\""}},
    {"components_not_array.json", {"water.waves.components: expected an array of objects, got object"}},
    // Medium.
    {"medium_negative_sigma_a.json", {"medium.sigma_a[1]: -0.1 is out of range (accepted: 0 <= value <= 1e+06 1/m)"}},
    {"medium_g_one.json", {"medium.g: 1 is out of range (accepted: -1 < value < 1)"}},
    {"medium_unknown_preset.json",
     {"medium.preset: unknown value \"coastel\" (did you mean 'coastal'?)",
      "(accepted: one of pure, clear-ocean, coastal, turbid-harbour)"}},
    {"medium_preset_and_sigma.json",
     {"medium: both preset and sigma_a/sigma_s/g are given",
      "(accepted: either preset (one of pure, clear-ocean, coastal, turbid-harbour), or "
      "sigma_a and sigma_s with optional g)"}},
    // Sky and camera forms.
    {"sky_model_typo.json",
     {"sky.model: unknown value \"gradiant\" (did you mean 'gradient'?)", "(accepted: one of constant, gradient)"}},
    {"sky_gradient_missing_zenith.json",
     {"sky.zenith: missing required field",
      "(accepted: an array of 3 numbers, each 0 <= value <= 1e+30 W m^-2 sr^-1)"}},
    {"sky_exponent_zero.json", {"sky.exponent: 0 is out of range (accepted: value > 0)"}},
    {"camera_target_and_direction.json",
     {"camera: both target and direction are given", "(accepted: exactly one of target, direction)"}},
    {"camera_direction_zero.json", {"camera.direction: [0, 0, 0] has no direction (accepted: a non-zero vector)"}},
    // Receivers.
    {"receiver_unknown_type.json",
     {"receivers[0].type: unknown value \"sphre\" (did you mean 'sphere'?)",
      "(accepted: one of plane, box, sphere, terrain, gltf)"}},
    {"receiver_type_typo.json", {"receivers[0].tpye: unknown field (did you mean 'type'?)"}},
    {"receiver_field_of_other_type.json",
     {"receivers[0].half_size: unknown field",
      "(accepted: name, type, albedo, translation, rotation_deg, scale, radius)"}},
    {"receiver_sphere_radius_zero.json", {"receivers[0].radius: 0 is out of range (accepted: 0 < value <= 1e+05 m)"}},
    {"receiver_scale_zero.json", {"receivers[0].scale[1]: 0 is out of range (accepted: 0 < value <= 1e+05)"}},
    {"receiver_albedo_above_one.json", {"receivers[0].albedo[0]: 1.5 is out of range (accepted: 0 <= value <= 1)"}},
    {"receiver_not_object.json", {"receivers[0]: expected an object, got number 3"}},
    {"terrain_resolution_4096.json",
     {"receivers[0].resolution: 4096 is out of range", "(accepted: an integer, 2 <= value <= 2048 cells per side)"}},
    {"gltf_missing_file.json",
     {"receivers[0].file: cannot open glTF file '", "tests/scene/bad/no_such_rock.gltf': No such file or directory"}},
    // Effects.
    {"effect_mode_unknown.json", {"effects.caustics.mode: unknown value \"maybe\" (accepted: one of auto, on, off)"}},
    {"effect_name_typo.json",
     {"effects.caustic: unknown field (did you mean 'caustics'?)",
      "(accepted: water, underwater_view, reflection, refraction, refraction_second_layer, caustics, godrays, "
      "caustic_blur)"}},
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
                             std::replace_if(
                                 name.begin(), name.end(), [](char c) { return !std::isalnum(c); }, '_');
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
