#include "tools/vkwater/view/camera_controller.hpp"

#include <algorithm>
#include <cmath>

namespace vkw::window {
namespace {

constexpr double kDegToRad = 3.14159265358979323846 / 180.0;
constexpr double kMinDistance = 0.05;  // m: the orbit never reaches its target

}  // namespace

const char* camera_mode_name(CameraMode mode) { return mode == CameraMode::Orbit ? "orbit" : "fly"; }

void CameraController::set_pose(const glm::dvec3& position, const glm::dvec3& target) {
    position_ = position;
    target_ = target;
    const glm::dvec3 d = target - position;
    distance_ = std::max(glm::length(d), kMinDistance);
    const glm::dvec3 dir = d / distance_;
    yaw_deg_ = std::atan2(dir.x, -dir.z) / kDegToRad;
    // Only the controller's own turns are clamped: a pose given exactly stays exact.
    pitch_deg_ = std::asin(std::clamp(dir.y, -1.0, 1.0)) / kDegToRad;
    speed_ = std::clamp(0.5 * distance_, 0.5, 50.0);
    velocity_ = glm::dvec3(0.0);
}

glm::dvec3 CameraController::forward() const {
    const double yaw = yaw_deg_ * kDegToRad, pitch = pitch_deg_ * kDegToRad;
    return {std::cos(pitch) * std::sin(yaw), std::sin(pitch), -std::cos(pitch) * std::cos(yaw)};
}

// Orbit keeps the target and moves the camera onto its sphere; fly keeps the camera and moves
// the target (the point `distance` ahead, where an orbit would turn about).
void CameraController::place_from_angles(bool keep_target) {
    if (keep_target) {
        position_ = target_ - forward() * distance_;
    } else {
        target_ = position_ + forward() * distance_;
    }
}

void CameraController::update(const CameraInput& input) {
    const double dt = std::max(input.dt, 0.0);
    bool turned = false;
    if (input.drag != glm::dvec2(0.0)) {
        yaw_deg_ += input.drag.x * kTurnDegPerPixel;
        // Dragging up looks up in fly mode; in orbit it lifts the camera, which looks down.
        const double sign = mode_ == CameraMode::Fly ? -1.0 : 1.0;
        pitch_deg_ = std::clamp(pitch_deg_ + sign * input.drag.y * kTurnDegPerPixel, -kMaxPitchDeg, kMaxPitchDeg);
        turned = true;
    }
    if (input.wheel != 0.0) {
        if (mode_ == CameraMode::Orbit) {
            distance_ = std::max(distance_ * std::pow(kWheelFactor, input.wheel), kMinDistance);
            turned = true;
        } else {
            speed_ = std::clamp(speed_ * std::pow(1.0 / kWheelFactor, input.wheel), 0.01, 1000.0);
        }
    }
    if (turned) place_from_angles(mode_ == CameraMode::Orbit);

    // From the yaw alone, so that they stay defined for a pose looking straight up or down.
    const double yaw = yaw_deg_ * kDegToRad;
    const glm::dvec3 ahead = forward();
    const glm::dvec3 flat_ahead(std::sin(yaw), 0.0, -std::cos(yaw));
    const glm::dvec3 right(std::cos(yaw), 0.0, std::sin(yaw));
    const glm::dvec3 up(0.0, 1.0, 0.0);
    if (mode_ == CameraMode::Orbit && input.pan != glm::dvec2(0.0)) {
        // The target follows the mouse across the view plane, at a rate that keeps the
        // point under the cursor roughly under it (scaled by the orbit distance).
        const glm::dvec3 view_up = glm::cross(right, ahead);
        const glm::dvec3 shift = (-input.pan.x * right + input.pan.y * view_up) * (distance_ * 0.002);
        target_ += shift;
        position_ += shift;
    }

    double speed = speed_;
    if (input.fast) speed *= kFastFactor;
    if (input.slow) speed /= kFastFactor;
    // Orbit moves over the ground (forward without its pitch); fly moves along the view.
    const glm::dvec3 along = mode_ == CameraMode::Fly ? ahead : flat_ahead;
    const glm::dvec3 wanted = (input.move.x * right + input.move.y * up + input.move.z * along) * speed;
    // Eased: the velocity approaches the keys' velocity exponentially, exact for any dt.
    velocity_ += (wanted - velocity_) * (1.0 - std::exp(-dt / kEaseSeconds));
    if (glm::length(velocity_) < 1e-6 * speed && wanted == glm::dvec3(0.0)) velocity_ = glm::dvec3(0.0);
    if (velocity_ != glm::dvec3(0.0)) {
        position_ += velocity_ * dt;
        target_ += velocity_ * dt;
    }
}

}  // namespace vkw::window
