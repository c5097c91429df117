// One command buffer and the fence of its last submission. The sample runs one frame at a time,
// which is also what vkwater asks (world.hpp): a frame's submission must have finished before the
// next frame's record() is submitted, since vkwater reuses its own images from frame to frame.
#pragma once

#include <vulkan/vulkan.h>

#include <cstdint>

namespace embed_host {

class FrameCommands {
public:
    FrameCommands(VkDevice device, uint32_t queue_family);
    ~FrameCommands();
    FrameCommands(const FrameCommands&) = delete;
    FrameCommands& operator=(const FrameCommands&) = delete;

    // Waits for the last submission, then begins the command buffer anew (one-time submit).
    VkCommandBuffer begin();
    // Ends the command buffer and submits it. Optional: a semaphore to wait for before `wait_stages`
    // (a swapchain image's acquisition) and one to signal when done (for its presentation).
    void submit(VkQueue queue, VkSemaphore wait = VK_NULL_HANDLE, VkPipelineStageFlags2 wait_stages = 0,
                VkSemaphore signal = VK_NULL_HANDLE);
    // Blocks until the last submission has finished (returns at once when none is in flight).
    void wait();

private:
    void release();
    VkDevice device_;
    VkCommandPool pool_ = VK_NULL_HANDLE;
    VkCommandBuffer cmd_ = VK_NULL_HANDLE;
    VkFence fence_ = VK_NULL_HANDLE;
    bool in_flight_ = false;  // submitted, and not yet waited for
};

}  // namespace embed_host
