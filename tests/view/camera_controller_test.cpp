// The viewer's camera controller (tools/vkwater/view/camera_controller.hpp), fed inputs directly:
// exact poses, orbit geometry, the pitch limit against view_matrix's switch of the up vector,
// eased motion at the stated speeds, and a continuous path through the water surface.
#include "tools/vkwater/view/camera_controller.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <tuple>

namespace vkw::window {
namespace {

constexpr double kDt = 1.0 / 60.0;

TEST(CameraController, SetPoseIsReturnedBitForBit) {
    CameraController camera;
    const glm::dvec3 position(0.1, 1.2, 4.3), target(-0.7, -1.5, -2.1);
    camera.set_pose(position, target);
    EXPECT_EQ(camera.position(), position);
    EXPECT_EQ(camera.target(), target);
    camera.update({kDt});  // no input: nothing moves
    EXPECT_EQ(camera.position(), position);
    EXPECT_EQ(camera.target(), target);
}

TEST(CameraController, OrbitTurnsAroundTheTargetAtItsDistance) {
    CameraController camera;
    camera.set_pose({0, 2, 5}, {0, 0, 0});
    const double distance = std::sqrt(29.0);
    CameraInput input{kDt};
    input.drag = {40.0, -12.0};
    camera.update(input);
    EXPECT_EQ(camera.target(), glm::dvec3(0.0));
    // Rebuilt from angles in double: a few roundings of 2^-53 on values of order 5.
    EXPECT_NEAR(glm::length(camera.position() - camera.target()), distance, 1e-12);
    // Looking along -z is yaw 0; dragging right turns it by kTurnDegPerPixel per pixel.
    EXPECT_NEAR(camera.yaw_deg(), 40.0 * CameraController::kTurnDegPerPixel, 1e-9);
    input = {kDt};
    input.wheel = 2.0;  // two steps closer
    camera.update(input);
    EXPECT_NEAR(camera.distance(), distance * 0.81, 1e-12);
}

TEST(CameraController, PitchStopsShortOfTheUpVectorSwitch) {
    for (CameraMode mode : {CameraMode::Orbit, CameraMode::Fly}) {
        CameraController camera;
        camera.set_mode(mode);
        camera.set_pose({0, 1, 3}, {0, 0, 0});
        for (double drag : {-1e5, 1e5}) {
            CameraInput input{kDt};
            input.drag = {0.0, drag};
            camera.update(input);
            EXPECT_EQ(std::abs(camera.pitch_deg()), CameraController::kMaxPitchDeg);
            // view_matrix switches "up" from +y to -z beyond |dir.y| = 0.999 (87.4 degrees).
            const glm::dvec3 dir = glm::normalize(camera.target() - camera.position());
            EXPECT_LT(std::abs(dir.y), 0.999);
        }
    }
}

// Holding W for T seconds in steps of dt: the velocity eases toward the speed as
// v_k = s (1 - a^k), a = exp(-dt / tau), so the distance is dt s sum_{k=1..n} (1 - a^k).
double eased_distance(double speed, int steps) {
    const double a = std::exp(-kDt / CameraController::kEaseSeconds);
    return kDt * speed * (steps - a * (1.0 - std::pow(a, steps)) / (1.0 - a));
}

TEST(CameraController, FlyMovesAlongTheViewAtTheEasedSpeed) {
    CameraController camera;
    camera.set_mode(CameraMode::Fly);
    camera.set_pose({0, 1, 4}, {0, 0, 0});  // distance sqrt(17): base speed half of it
    const glm::dvec3 start = camera.position();
    const glm::dvec3 view = glm::normalize(camera.target() - start);
    const int steps = 120;
    CameraInput input{kDt};
    input.move = {0.0, 0.0, 1.0};
    for (int i = 0; i < steps; ++i) camera.update(input);
    const glm::dvec3 moved = camera.position() - start;
    // 120 steps of sums of a few roundings each, on values of order 1: 1e-12 is generous.
    EXPECT_NEAR(glm::length(moved), eased_distance(camera.speed(), steps), 1e-12);
    EXPECT_NEAR(glm::dot(glm::normalize(moved), view), 1.0, 1e-12);
}

TEST(CameraController, ShiftAndCtrlScaleTheSpeedFivefold) {
    for (auto [fast, slow, factor] :
         {std::tuple{false, false, 1.0}, std::tuple{true, false, 5.0}, std::tuple{false, true, 0.2}}) {
        CameraController camera;
        camera.set_pose({0, 0, 4}, {0, 0, 0});
        CameraInput input{kDt};
        input.move = {1.0, 0.0, 0.0};
        input.fast = fast;
        input.slow = slow;
        for (int i = 0; i < 600; ++i) camera.update(input);  // 10 s: a^600 = e^-125, converged
        EXPECT_NEAR(glm::length(camera.velocity()), camera.speed() * factor, 1e-12 * camera.speed());
    }
}

TEST(CameraController, FliesThroughTheWaterSurfaceWithoutAJump) {
    CameraController camera;
    camera.set_mode(CameraMode::Fly);
    camera.set_pose({0, 0.5, 3}, {0, 0.5, 0});
    CameraInput input{kDt};
    input.move = {0.0, -1.0, 0.0};  // Q: straight down
    double last_y = camera.position().y;
    bool crossed = false;
    for (int i = 0; i < 120; ++i) {
        camera.update(input);
        const double y = camera.position().y;
        EXPECT_LE(y, last_y);                                       // monotonic
        EXPECT_LE(last_y - y, camera.speed() * kDt * (1 + 1e-12));  // never faster than the speed
        crossed |= last_y >= 0.0 && y < 0.0;
        last_y = y;
    }
    EXPECT_TRUE(crossed);
    EXPECT_LT(last_y, -0.5);
}

}  // namespace
}  // namespace vkw::window
