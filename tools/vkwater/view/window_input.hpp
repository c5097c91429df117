// The keyboard and mouse, read once per frame: the camera's input (held keys, drags, the
// wheel) and the viewer's shortcuts (each press counts once, even a tap shorter than a
// frame: the window collects them), leaving out whatever Dear ImGui takes (the pointer over a
// panel, a focused text field).
#pragma once

#include "engine/window/glfw_window.hpp"
#include "tools/vkwater/view/camera_controller.hpp"
#include "tools/vkwater/view/parameter_panel.hpp"

namespace vkw::window {

class WindowInput {
public:
    explicit WindowInput(GlfwWindow& window) : window_(window) {}

    // Applies the shortcuts to `controls` (Esc asks the window to close) and returns the
    // camera's input for a frame of `dt` seconds.
    CameraInput read(double dt, bool ui_wants_mouse, bool ui_wants_keyboard, ViewControls& controls);

private:
    bool held(int key) const;
    void apply_shortcut(int key, ViewControls& controls);
    GlfwWindow& window_;
};

}  // namespace vkw::window
