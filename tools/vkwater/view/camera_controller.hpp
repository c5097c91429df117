// The viewer's camera: orbit (around a target point) and fly (free, first person) modes,
// driven by mouse and keys, with no window or Vulkan in sight (tests feed it inputs).
//
// Orbit: dragging turns the camera around the target at a fixed distance, the wheel moves
// it closer or farther, WASD/QE move target and camera together. Fly: dragging turns the
// view about the camera, WASD move along the view and sideways, Q/E down and up, the wheel
// scales the speed. Shift moves 5x faster, Ctrl 5x slower. Motion is eased (the velocity
// follows the keys with a 0.08 s time constant), and nothing happens at the water surface:
// the camera passes through it continuously, and the renderer's stencil split shades the
// frames in which the near plane straddles it.
//
// The pitch stays within +-85 degrees, short of vkw::view_matrix's switch of the up vector
// (about 87.4 degrees), so the picture never turns about the view axis. A pose set with
// set_pose is returned exactly (bit for bit) until the camera moves.
#pragma once

#include <glm/glm.hpp>

#include <cstdint>

namespace vkw::window {

enum class CameraMode : uint8_t { Orbit, Fly };
const char* camera_mode_name(CameraMode mode);

struct CameraInput {
    double dt = 0.0;       // seconds since the last update, >= 0
    glm::dvec2 drag{0.0};  // pixels the mouse moved with the turn button held (x right, y down)
    glm::dvec2 pan{0.0};   // pixels the mouse moved with the pan button held (orbit only)
    double wheel = 0.0;    // wheel steps, positive away from the user
    glm::dvec3 move{0.0};  // keys: x right (D - A), y up (E - Q), z forward (W - S)
    bool fast = false;     // Shift
    bool slow = false;     // Ctrl
};

class CameraController {
public:
    static constexpr double kMaxPitchDeg = 85.0;
    static constexpr double kTurnDegPerPixel = 0.25;
    static constexpr double kEaseSeconds = 0.08;
    static constexpr double kFastFactor = 5.0;
    static constexpr double kWheelFactor = 0.9;  // orbit distance per wheel step toward the target

    // Also sets the base speed from the distance: half of it per second, in [0.5, 50] m/s.
    void set_pose(const glm::dvec3& position, const glm::dvec3& target);
    void set_mode(CameraMode mode) { mode_ = mode; }
    CameraMode mode() const { return mode_; }
    void update(const CameraInput& input);

    glm::dvec3 position() const { return position_; }
    glm::dvec3 target() const { return target_; }
    double yaw_deg() const { return yaw_deg_; }      // 0 looks along -z, 90 along +x
    double pitch_deg() const { return pitch_deg_; }  // positive looks up
    double distance() const { return distance_; }
    double speed() const { return speed_; }  // base speed, m/s
    glm::dvec3 velocity() const { return velocity_; }

private:
    glm::dvec3 forward() const;
    void place_from_angles(bool keep_target);
    CameraMode mode_ = CameraMode::Orbit;
    glm::dvec3 position_{0.0, 0.0, 1.0};
    glm::dvec3 target_{0.0};
    double yaw_deg_ = 0.0;
    double pitch_deg_ = 0.0;
    double distance_ = 1.0;
    double speed_ = 0.5;
    glm::dvec3 velocity_{0.0};  // eased, world space, m/s
};

}  // namespace vkw::window
