// The window of `vkwater view`: GLFW (X11 here) without a client API, so that Vulkan presents
// to it. Owns GLFW's initialisation. Reports the framebuffer size (0 x 0 while minimised) and
// whether it changed, and turns a missing display into one clear message instead of GLFW's
// error code. Input that can begin and end between two frames (a key tap, a quick drag, the
// wheel) is collected by callbacks as it arrives, so that a slow frame loses none of it;
// Dear ImGui's callbacks, installed later, chain to these.
#pragma once

#include <vulkan/vulkan.h>

#include <glm/glm.hpp>

#include <cstdint>
#include <string>
#include <vector>

struct GLFWwindow;

namespace vkw::window {

class GlfwWindow {
public:
    // Throws InternalError naming GLFW's reason when there is no display to open a window
    // on (DISPLAY unset, no X server) or the Vulkan loader cannot present to it.
    GlfwWindow(uint32_t width, uint32_t height, const std::string& title);
    ~GlfwWindow();
    GlfwWindow(const GlfwWindow&) = delete;
    GlfwWindow& operator=(const GlfwWindow&) = delete;

    GLFWwindow* handle() const { return window_; }
    // What vkCreateInstance needs for a surface of this window system.
    static std::vector<std::string> required_instance_extensions();
    // The caller owns the surface (the swapchain destroys it).
    VkSurfaceKHR create_surface(VkInstance instance) const;

    VkExtent2D framebuffer_size() const;  // pixels; 0 x 0 while minimised
    // The primary monitor's refresh interval in milliseconds; 0 when the window system does not say.
    double refresh_interval_ms() const;
    bool should_close() const;
    void request_close();
    void poll_events();
    void wait_events();  // sleeps until an event arrives (a minimised window draws nothing)
    // Asks the window system for a new size and processes events until the framebuffer has
    // it; false when it did not arrive within `timeout_s` (a window manager may refuse).
    bool resize(uint32_t width, uint32_t height, double timeout_s);
    // True once after each change of the framebuffer size.
    bool take_resized();
    // Since the last call: wheel steps (positive away from the user), the keys pressed (GLFW
    // key codes, in order), and the cursor's motion in pixels with the left button held (drag)
    // and with the right or middle one held (pan).
    double take_scroll();
    std::vector<int> take_key_presses();
    glm::dvec2 take_drag();
    glm::dvec2 take_pan();

private:
    static GlfwWindow& of(GLFWwindow* window);
    static void on_framebuffer_size(GLFWwindow* window, int width, int height);
    static void on_scroll(GLFWwindow* window, double x, double y);
    static void on_key(GLFWwindow* window, int key, int scancode, int action, int mods);
    static void on_cursor(GLFWwindow* window, double x, double y);
    GLFWwindow* window_ = nullptr;
    bool resized_ = false;
    double scroll_ = 0.0;
    std::vector<int> key_presses_;
    glm::dvec2 cursor_{0.0};
    bool has_cursor_ = false;
    glm::dvec2 drag_{0.0}, pan_{0.0};
};

}  // namespace vkw::window
