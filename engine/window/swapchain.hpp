// The window's swapchain: the surface, its format and present mode, the images and their
// views, and recreation at a new size (resize; out-of-date or suboptimal after acquire or
// present). Prefers an 8-bit UNORM format in the sRGB colour space: the present tonemap then
// encodes sRGB itself, exactly as the PNG preview does, and Dear ImGui's colours (given in
// sRGB) are written unchanged; an _SRGB format is taken when no UNORM one is offered.
#pragma once

#include <vulkan/vulkan.h>

#include <cstdint>
#include <string>
#include <vector>

namespace vkw {
class Context;
}

namespace vkw::window {

enum class PresentMode : uint8_t { Fifo, Mailbox, Immediate };
const char* present_mode_name(PresentMode mode);

// What acquire and present report; the caller recreates on anything but Ok.
enum class SwapchainStatus : uint8_t { Ok, Suboptimal, OutOfDate };

class Swapchain {
public:
    // Takes ownership of `surface`. Throws InternalError when the device's queue cannot
    // present to it. `wanted` falls back to FIFO (always supported) with a note on stderr.
    Swapchain(Context& context, VkSurfaceKHR surface, PresentMode wanted);
    ~Swapchain();
    Swapchain(const Swapchain&) = delete;
    Swapchain& operator=(const Swapchain&) = delete;

    // (Re)creates the swapchain for a framebuffer of `size` (clamped to what the surface
    // allows; not 0 x 0). Waits for the device: the old images may still be in use.
    void recreate(VkExtent2D size);

    // Acquires the next image, signalling `acquired` (not on OutOfDate).
    SwapchainStatus acquire(VkSemaphore acquired, uint32_t& index);
    // Presents image `index` once `rendered` is signalled.
    SwapchainStatus present(VkSemaphore rendered, uint32_t index);

    VkFormat format() const { return format_.format; }
    bool encodes_srgb() const;  // the format is _SRGB: writes are encoded by the hardware
    VkExtent2D extent() const { return extent_; }
    PresentMode mode() const { return mode_; }
    uint32_t image_count() const { return static_cast<uint32_t>(images_.size()); }
    VkImage image(uint32_t index) const { return images_[index]; }
    VkImageView view(uint32_t index) const { return views_[index]; }
    // Counts recreations: whatever was made for the old images is stale when it changes.
    uint64_t generation() const { return generation_; }

private:
    void destroy_views();
    Context& context_;
    VkSurfaceKHR surface_ = VK_NULL_HANDLE;
    VkSwapchainKHR swapchain_ = VK_NULL_HANDLE;
    VkSurfaceFormatKHR format_{};
    PresentMode mode_ = PresentMode::Fifo;
    VkExtent2D extent_{};
    std::vector<VkImage> images_;
    std::vector<VkImageView> views_;
    uint64_t generation_ = 0;
};

}  // namespace vkw::window
