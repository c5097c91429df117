// Overrides ("key.path=value", the CLI's --set) applied before validation.
#include <gtest/gtest.h>

#include "engine/scene/scene_loader.hpp"
#include "tests/scene/scene_test_support.hpp"

namespace vkw {
namespace {

Scene with(const std::vector<std::string>& overrides) {
    return parse_scene(test::kMinimalScene, "min.json", overrides);
}

std::string error_with(const std::vector<std::string>& overrides) {
    return test::user_error_of([&] { with(overrides); });
}

TEST(scene_overrides, NumberVectorAndString) {
    const Scene scene = with({"camera.fov_y_deg=75", "sun.irradiance=[2, 2.5, 3]", "description=tiled pool test"});
    EXPECT_EQ(scene.camera.fov_y_deg, 75.0);
    EXPECT_EQ(scene.sun.irradiance, glm::dvec3(2.0, 2.5, 3.0));
    EXPECT_EQ(scene.description, "tiled pool test");
    // A JSON string literal is the same string.
    EXPECT_EQ(with({R"(description="quoted")"}).description, "quoted");
}

TEST(scene_overrides, AppliedInOrderAndOnTopOfTheFile) {
    const Scene scene = load_scene(test::kSourceDir / "scenes/pool.json", {"camera.far=100", "camera.far=200"});
    EXPECT_EQ(scene.camera.far_plane, 200.0);
    EXPECT_EQ(scene.camera.fov_y_deg, 60.0);  // untouched fields keep the file's values
}

TEST(scene_overrides, CreatesAbsentSections) { EXPECT_EQ(with({"floor.height=-2"}).floor.height, -2.0); }

TEST(scene_overrides, NullRemovesAFieldSoTheSunFormCanChange) {
    const Scene scene = with({"sun.elevation_deg=null", "sun.direction=[0,-2,0]"});
    EXPECT_EQ(scene.sun.direction, glm::dvec3(0.0, -1.0, 0.0));
}

TEST(scene_overrides, UnknownKeyIsRefusedWithHintAndOverrideNamed) {
    const std::string message = error_with({"camera.fovy=75"});
    EXPECT_NE(message.find("min.json: camera.fovy: unknown field (did you mean 'fov_y_deg'?)"), std::string::npos)
        << message;
    EXPECT_NE(message.find("[from override 'camera.fovy=75']"), std::string::npos) << message;
    EXPECT_NE(error_with({"camra.fov_y_deg=75"}).find("camra: unknown field (did you mean 'camera'?)"),
              std::string::npos);
}

TEST(scene_overrides, OutOfRangeValueNamesTheOverride) {
    const std::string message = error_with({"camera.fov_y_deg=0"});
    EXPECT_EQ(message,
              "min.json: camera.fov_y_deg: 0 is out of range (accepted: 1 < value < 179 degrees) "
              "[from override 'camera.fov_y_deg=0']");
}

// A --set value may hold any bytes: bytes that are not UTF-8 are still a user error (quoted with
// U+FFFD in their place), not an exception from the JSON library.
TEST(scene_overrides, ValuesThatAreNotUtf8AreAUserError) {
    const std::string message = error_with({"water.level=\"\xff\xfe\""});
    EXPECT_NE(message.find("water.level: expected a number, got string"), std::string::npos) << message;
    EXPECT_NE(message.find("\xef\xbf\xbd"), std::string::npos) << message;  // U+FFFD in UTF-8
}

// A value nested 10^5 deep is refused by the parse (it would overflow the stack of the code that
// prints it), and the override is quoted cut, with its length, so the message stays one line.
TEST(scene_overrides, ADeeplyNestedValueIsRefusedAndQuotedShortened) {
    const std::string message = error_with({"water.level=" + std::string(100000, '[') + std::string(100000, ']')});
    EXPECT_LT(message.size(), 400u) << message.substr(0, 400);
    EXPECT_NE(message.find("nested too deeply (accepted: at most 64 levels of objects and arrays)"), std::string::npos)
        << message.substr(0, 400);
    EXPECT_NE(message.find("... (200012 characters)"), std::string::npos) << message.substr(0, 400);
}

// Brackets inside a string are text, not nesting.
TEST(scene_overrides, BracketsInsideAStringAreNotNesting) {
    const std::string message = error_with({"water.level=\"" + std::string(100, '[') + "\\\"\""});
    EXPECT_EQ(message.find("nested too deeply"), std::string::npos) << message;
    EXPECT_NE(message.find("expected a number, got string"), std::string::npos) << message;
}

TEST(scene_overrides, NonFiniteValuesAreRefused) {
    for (const char* value : {"nan", "NaN", "inf", "-inf", "1e999", "-1e999"}) {
        const std::string message = error_with({std::string("camera.near=") + value});
        EXPECT_NE(message.find("camera.near: string \""), std::string::npos) << message;
        EXPECT_NE(message.find("is not a finite number (accepted: 0 < value <= 1e+05 m)"), std::string::npos)
            << message;
    }
    const std::string in_vector = error_with({"sky.radiance=[1, 1e999, 1]"});
    EXPECT_NE(in_vector.find("sky.radiance: expected an array of 3 numbers, got string"), std::string::npos)
        << in_vector;
}

TEST(scene_overrides, MalformedOverridesAreRefused) {
    EXPECT_NE(error_with({"camera.fov_y_deg"}).find("override 'camera.fov_y_deg': no '=' in the override"),
              std::string::npos);
    EXPECT_NE(error_with({"camera..near=1"}).find("empty field name"), std::string::npos);
    EXPECT_NE(error_with({"=1"}).find("empty field name"), std::string::npos);
    EXPECT_NE(error_with({"sky.radiance.x=1"})
                  .find("sky.radiance: override 'sky.radiance.x=1' sets a field "
                        "inside a value that is not an object"),
              std::string::npos);
    EXPECT_NE(error_with({"floor.height=null"}).find("removes a field that the scene does not have"),
              std::string::npos);
    // A string where a number belongs is a type error, not a crash.
    EXPECT_NE(error_with({"camera.fov_y_deg=wide"}).find("camera.fov_y_deg: expected a number, got string \"wide\""),
              std::string::npos);
}

}  // namespace
}  // namespace vkw
