// Dear ImGui for the window: its context, the GLFW platform backend (whose input callbacks
// chain to the window's own) and the Vulkan renderer backend. Debian's Dear ImGui 1.86 makes
// its one pipeline for a VkRenderPass at initialisation; it is connected to the render pass of
// the present graph's overlay pass (FrameExecutor::render_pass), and that pipeline then serves
// every compatible render pass (same colour format, one sample): the overlay passes of the
// other swapchain images and of later graphs. A new swapchain format reconnects it.
#pragma once

#include <vulkan/vulkan.h>

#include <cstdint>

struct GLFWwindow;

namespace vkw {
class Context;
}

namespace vkw::window {

class ImGuiLayer {
public:
    // `frames_in_flight`: ImGui keeps that many vertex buffers and uses one per frame in turn,
    // so a buffer is rewritten only after the frame that read it has finished.
    ImGuiLayer(Context& context, GLFWwindow* window, uint32_t frames_in_flight);
    ~ImGuiLayer();
    ImGuiLayer(const ImGuiLayer&) = delete;
    ImGuiLayer& operator=(const ImGuiLayer&) = delete;

    // (Re)initialises the renderer backend for render passes compatible with `render_pass`
    // and uploads the font atlas. Waits for the device.
    void connect(VkRenderPass render_pass, VkFormat format);
    VkFormat connected_format() const { return format_; }

    void new_frame();     // starts the UI of a frame (connect first)
    void finish_frame();  // ends it: ImGui::Render
    // Records the finished frame's draw calls, inside the overlay pass's render pass.
    void record(VkCommandBuffer cmd) const;

    bool wants_mouse() const;     // the pointer is over a panel: the camera ignores it
    bool wants_keyboard() const;  // a text field has focus: the shortcuts are ignored

private:
    void disconnect();
    Context& context_;
    uint32_t frames_in_flight_;
    VkDescriptorPool pool_ = VK_NULL_HANDLE;
    VkFormat format_ = VK_FORMAT_UNDEFINED;
};

}  // namespace vkw::window
