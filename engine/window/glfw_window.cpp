#include "engine/window/glfw_window.hpp"

#include "engine/core/errors.hpp"
#include "engine/vk/check.hpp"

#define GLFW_INCLUDE_VULKAN
#include <GLFW/glfw3.h>

#include <algorithm>
#include <chrono>
#include <utility>

namespace vkw::window {
namespace {

// GLFW reports why it failed through a callback; the message quotes it.
std::string g_last_glfw_error;

void remember_glfw_error(int code, const char* description) {
    g_last_glfw_error =
        std::string(description ? description : "unknown") + " (GLFW error " + std::to_string(code) + ")";
}

constexpr const char* kDisplayHelp =
    "vkwater view needs a display: run it in an X11 session, or headless under a virtual X server "
    "(xvfb-run -a vkwater view ...; Debian: xvfb xauth)";

}  // namespace

GlfwWindow::GlfwWindow(uint32_t width, uint32_t height, const std::string& title) {
    glfwSetErrorCallback(remember_glfw_error);
    if (!glfwInit()) throw InternalError("no display: " + g_last_glfw_error + "; " + kDisplayHelp);
    if (!glfwVulkanSupported()) {
        glfwTerminate();
        throw InternalError(
            "the Vulkan loader cannot present to this display (GLFW finds no surface extension); "
            "install a Vulkan driver (Debian: mesa-vulkan-drivers)");
    }
    glfwWindowHint(GLFW_CLIENT_API, GLFW_NO_API);  // Vulkan draws, not OpenGL
    glfwWindowHint(GLFW_RESIZABLE, GLFW_TRUE);
    window_ = glfwCreateWindow(static_cast<int>(width), static_cast<int>(height), title.c_str(), nullptr, nullptr);
    if (!window_) {
        glfwTerminate();
        throw InternalError("no window: " + g_last_glfw_error + "; " + kDisplayHelp);
    }
    glfwSetWindowUserPointer(window_, this);
    // Installed before Dear ImGui's, which chains to them.
    glfwSetFramebufferSizeCallback(window_, on_framebuffer_size);
    glfwSetScrollCallback(window_, on_scroll);
    glfwSetKeyCallback(window_, on_key);
    glfwSetCursorPosCallback(window_, on_cursor);
}

GlfwWindow::~GlfwWindow() {
    if (window_) glfwDestroyWindow(window_);
    glfwTerminate();
}

std::vector<std::string> GlfwWindow::required_instance_extensions() {
    uint32_t count = 0;
    const char** names = glfwGetRequiredInstanceExtensions(&count);
    return std::vector<std::string>(names, names + count);
}

VkSurfaceKHR GlfwWindow::create_surface(VkInstance instance) const {
    VkSurfaceKHR surface = VK_NULL_HANDLE;
    VKW_CHECK(glfwCreateWindowSurface(instance, window_, nullptr, &surface), "window surface");
    return surface;
}

VkExtent2D GlfwWindow::framebuffer_size() const {
    int width = 0, height = 0;
    glfwGetFramebufferSize(window_, &width, &height);
    return {static_cast<uint32_t>(std::max(width, 0)), static_cast<uint32_t>(std::max(height, 0))};
}

double GlfwWindow::refresh_interval_ms() const {
    GLFWmonitor* monitor = glfwGetPrimaryMonitor();
    const GLFWvidmode* mode = monitor ? glfwGetVideoMode(monitor) : nullptr;
    return mode && mode->refreshRate > 0 ? 1000.0 / mode->refreshRate : 0.0;
}

bool GlfwWindow::should_close() const { return glfwWindowShouldClose(window_); }
void GlfwWindow::request_close() { glfwSetWindowShouldClose(window_, GLFW_TRUE); }
void GlfwWindow::poll_events() { glfwPollEvents(); }
void GlfwWindow::wait_events() { glfwWaitEvents(); }

bool GlfwWindow::resize(uint32_t width, uint32_t height, double timeout_s) {
    glfwSetWindowSize(window_, static_cast<int>(width), static_cast<int>(height));
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::duration<double>(timeout_s);
    while (true) {
        const VkExtent2D size = framebuffer_size();
        if (size.width == width && size.height == height) return true;
        if (std::chrono::steady_clock::now() > deadline) return false;
        glfwWaitEventsTimeout(0.01);
    }
}

bool GlfwWindow::take_resized() { return std::exchange(resized_, false); }
double GlfwWindow::take_scroll() { return std::exchange(scroll_, 0.0); }
std::vector<int> GlfwWindow::take_key_presses() { return std::exchange(key_presses_, {}); }
glm::dvec2 GlfwWindow::take_drag() { return std::exchange(drag_, glm::dvec2(0.0)); }
glm::dvec2 GlfwWindow::take_pan() { return std::exchange(pan_, glm::dvec2(0.0)); }

GlfwWindow& GlfwWindow::of(GLFWwindow* window) { return *static_cast<GlfwWindow*>(glfwGetWindowUserPointer(window)); }

void GlfwWindow::on_framebuffer_size(GLFWwindow* window, int, int) { of(window).resized_ = true; }

void GlfwWindow::on_scroll(GLFWwindow* window, double, double y) { of(window).scroll_ += y; }

void GlfwWindow::on_key(GLFWwindow* window, int key, int, int action, int) {
    if (action == GLFW_PRESS) of(window).key_presses_.push_back(key);
}

void GlfwWindow::on_cursor(GLFWwindow* window, double x, double y) {
    GlfwWindow& self = of(window);
    const glm::dvec2 cursor(x, y);
    if (self.has_cursor_) {
        const glm::dvec2 delta = cursor - self.cursor_;
        // The buttons' state as of this event: events arrive in order within glfwPollEvents.
        if (glfwGetMouseButton(window, GLFW_MOUSE_BUTTON_LEFT) == GLFW_PRESS) self.drag_ += delta;
        if (glfwGetMouseButton(window, GLFW_MOUSE_BUTTON_RIGHT) == GLFW_PRESS ||
            glfwGetMouseButton(window, GLFW_MOUSE_BUTTON_MIDDLE) == GLFW_PRESS) {
            self.pan_ += delta;
        }
    }
    self.cursor_ = cursor;
    self.has_cursor_ = true;
}

}  // namespace vkw::window
