#include "tools/vkwater/view/window_input.hpp"

#include <GLFW/glfw3.h>

namespace vkw::window {

bool WindowInput::held(int key) const { return glfwGetKey(window_.handle(), key) == GLFW_PRESS; }

void WindowInput::apply_shortcut(int key, ViewControls& controls) {
    switch (key) {
        case GLFW_KEY_SPACE: controls.paused = !controls.paused; break;
        case GLFW_KEY_N: controls.step = true; break;
        case GLFW_KEY_F12: controls.screenshot = true; break;
        case GLFW_KEY_F5: controls.reload_shaders = true; break;
        case GLFW_KEY_F1: controls.show_panels = !controls.show_panels; break;
        case GLFW_KEY_TAB:
            controls.camera_mode = controls.camera_mode == CameraMode::Orbit ? CameraMode::Fly : CameraMode::Orbit;
            break;
        case GLFW_KEY_ESCAPE: window_.request_close(); break;
        default: break;
    }
}

CameraInput WindowInput::read(double dt, bool ui_wants_mouse, bool ui_wants_keyboard, ViewControls& controls) {
    CameraInput input;
    input.dt = dt;
    // Taken every frame, so that what a panel got does not move the camera later.
    const glm::dvec2 drag = window_.take_drag(), pan = window_.take_pan();
    const double wheel = window_.take_scroll();
    const std::vector<int> presses = window_.take_key_presses();
    if (!ui_wants_mouse) {
        input.drag = drag;
        input.pan = pan;
        input.wheel = wheel;
    }
    if (ui_wants_keyboard) return input;
    for (int key : presses) apply_shortcut(key, controls);
    // Movement follows the keys held now: a tap shorter than a frame moves nothing.
    input.move = {double(held(GLFW_KEY_D)) - double(held(GLFW_KEY_A)),
                  double(held(GLFW_KEY_E)) - double(held(GLFW_KEY_Q)),
                  double(held(GLFW_KEY_W)) - double(held(GLFW_KEY_S))};
    input.fast = held(GLFW_KEY_LEFT_SHIFT) || held(GLFW_KEY_RIGHT_SHIFT);
    input.slow = held(GLFW_KEY_LEFT_CONTROL) || held(GLFW_KEY_RIGHT_CONTROL);
    return input;
}

}  // namespace vkw::window
