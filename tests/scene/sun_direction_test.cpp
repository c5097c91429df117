// Sun elevation/azimuth to direction, checked against values worked out by hand, and the
// direction form's normalisation.
#include <cmath>

#include <gtest/gtest.h>

#include "engine/scene/scene_loader.hpp"
#include "tests/scene/scene_test_support.hpp"

namespace vkw {
namespace {

Sun sun_from(const std::string& sun_json) {
    const std::string text = R"({ "camera": { "position": [0, 1, 3], "target": [0, 0, 0] },
                                  "sky": { "radiance": [1, 1, 1] }, "sun": )" +
                             sun_json + "}";
    return parse_scene(text, "sun.json").sun;
}

void expect_near(const glm::dvec3& actual, const glm::dvec3& expected, double tolerance = 1e-15) {
    EXPECT_NEAR(actual.x, expected.x, tolerance);
    EXPECT_NEAR(actual.y, expected.y, tolerance);
    EXPECT_NEAR(actual.z, expected.z, tolerance);
}

TEST(scene_sun_direction, OverheadIsExactlyDown) {
    // Exact, not merely close: an exactly vertical sun is the closed-form test case.
    EXPECT_EQ(sun_from(R"({ "elevation_deg": 90, "azimuth_deg": 0 })").direction, glm::dvec3(0.0, -1.0, 0.0));
    EXPECT_EQ(sun_from(R"({ "elevation_deg": 90, "azimuth_deg": 137 })").direction, glm::dvec3(0.0, -1.0, 0.0));
}

TEST(scene_sun_direction, HorizonAtCardinalAzimuthsIsExact) {
    // Toward the sun at azimuth 0 is -z (north), 90 is +x; the light travels the other way.
    EXPECT_EQ(direction_toward_sun(0.0, 0.0), glm::dvec3(0.0, 0.0, -1.0));
    EXPECT_EQ(direction_toward_sun(0.0, 90.0), glm::dvec3(1.0, 0.0, 0.0));
    EXPECT_EQ(direction_toward_sun(0.0, 180.0), glm::dvec3(0.0, 0.0, 1.0));
    EXPECT_EQ(direction_toward_sun(0.0, 270.0), glm::dvec3(-1.0, 0.0, 0.0));
    EXPECT_EQ(direction_toward_sun(0.0, -90.0), glm::dvec3(-1.0, 0.0, 0.0));
    EXPECT_EQ(sun_from(R"({ "elevation_deg": 0, "azimuth_deg": 90 })").direction, glm::dvec3(-1.0, 0.0, 0.0));
}

TEST(scene_sun_direction, ObliqueAnglesByHand) {
    const double h = std::sqrt(0.5);
    // el 45, az 0: toward (0, h, -h); travelling (0, -h, h).
    expect_near(sun_from(R"({ "elevation_deg": 45 })").direction, {0.0, -h, h});
    // el 30, az 90: toward (cos30, sin30, 0).
    expect_near(sun_from(R"({ "elevation_deg": 30, "azimuth_deg": 90 })").direction,
                {-std::sqrt(3.0) / 2.0, -0.5, 0.0});
    // el 60, az 45: toward (0.5 h, sqrt(3)/2, -0.5 h).
    expect_near(direction_toward_sun(60.0, 45.0), {0.5 * h, std::sqrt(3.0) / 2.0, -0.5 * h});
    // Below the horizon is allowed: the light then travels upward and lights nothing.
    expect_near(sun_from(R"({ "elevation_deg": -30, "azimuth_deg": 180 })").direction,
                {0.0, 0.5, -std::sqrt(3.0) / 2.0});
}

TEST(scene_sun_direction, IsUnitLengthForManyAngles) {
    for (double el = -90.0; el <= 90.0; el += 7.5) {
        for (double az = -360.0; az <= 360.0; az += 11.25) {
            EXPECT_NEAR(glm::length(direction_toward_sun(el, az)), 1.0, 1e-15) << el << " " << az;
        }
    }
}

TEST(scene_sun_direction, DirectionFormIsNormalised) {
    const Sun sun = sun_from(R"({ "direction": [3, -4, 0], "irradiance": [2, 2, 2] })");
    expect_near(sun.direction, {0.6, -0.8, 0.0});
    EXPECT_EQ(sun.irradiance, glm::dvec3(2.0));
    // Huge and tiny magnitudes normalise without overflow or underflow.
    expect_near(sun_from(R"({ "direction": [0, -1e300, 1e300] })").direction, {0.0, -std::sqrt(0.5), std::sqrt(0.5)});
    expect_near(sun_from(R"({ "direction": [0, -1e-300, 0] })").direction, {0.0, -1.0, 0.0});
}

}  // namespace
}  // namespace vkw
