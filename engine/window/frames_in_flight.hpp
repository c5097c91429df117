// Frames in flight: while the device renders frame k, the CPU already prepares frame k + 1.
// Each of the kSlots slots has a command buffer, a fence (signalled when the slot's last
// frame has finished on the device) and the semaphore its swapchain image is acquired with.
// Each swapchain image has its own "rendered" semaphore for presentation to wait on (a slot's
// semaphore could still be held by the presentation of an image acquired earlier).
//
// The frame graph's transient images and the window's HDR image are shared by every frame,
// so each submission also waits for the one before it through a chain of binary semaphores:
// frames overlap with the CPU's work, never with each other on the device. (A pipeline
// barrier cannot order two submissions here: synchronization validation would not see it,
// and the graph's first-use barriers wait for nothing by design.)
#pragma once

#include <vulkan/vulkan.h>

#include <array>
#include <cstdint>
#include <vector>

namespace vkw {
class Context;
}

namespace vkw::window {

class FramesInFlight {
public:
    static constexpr uint32_t kSlots = 2;

    struct Slot {
        VkCommandPool pool = VK_NULL_HANDLE;
        VkCommandBuffer cmd = VK_NULL_HANDLE;
        VkFence done = VK_NULL_HANDLE;          // signalled: the slot's last frame has finished
        VkSemaphore acquired = VK_NULL_HANDLE;  // the swapchain image may be written
        VkSemaphore chain = VK_NULL_HANDLE;     // this slot's frame has finished (for the next frame)
    };

    explicit FramesInFlight(Context& context);
    ~FramesInFlight();
    FramesInFlight(const FramesInFlight&) = delete;
    FramesInFlight& operator=(const FramesInFlight&) = delete;

    // Waits until the slot of the next frame is free and returns it, its command buffer reset.
    Slot& next_slot();
    // One "rendered" semaphore per swapchain image; call after (re)creating the swapchain
    // (the device is idle then).
    void set_image_count(uint32_t count);
    // Begins recording into the slot's command buffer.
    void begin(Slot& slot);
    // Ends and submits the slot's command buffer: waits for the acquired image (at colour
    // output) and for the previous frame; signals the image's "rendered" semaphore, the
    // chain and the slot's fence. Moves on to the next slot.
    void submit(Slot& slot, uint32_t image);
    VkSemaphore rendered(uint32_t image) const { return rendered_[image]; }
    // Waits until every submitted frame has finished (before work submitted outside the
    // chain: the per-pass timing frames, screenshots, recreation).
    void wait_all();

private:
    Context& context_;
    std::array<Slot, kSlots> slots_{};
    uint32_t current_ = 0;
    std::vector<VkSemaphore> rendered_;
    VkSemaphore pending_chain_ = VK_NULL_HANDLE;  // signalled by the last submission, not yet waited
};

}  // namespace vkw::window
