// FrameCommands (frame_commands.hpp).
#include "frame_commands.hpp"

#include "errors.hpp"

#include <cstdint>

namespace embed_host {

FrameCommands::FrameCommands(VkDevice device, uint32_t queue_family) : device_(device) {
    try {
        VkCommandPoolCreateInfo pool_info{};
        pool_info.sType = VK_STRUCTURE_TYPE_COMMAND_POOL_CREATE_INFO;
        pool_info.flags = VK_COMMAND_POOL_CREATE_RESET_COMMAND_BUFFER_BIT;
        pool_info.queueFamilyIndex = queue_family;
        check(vkCreateCommandPool(device_, &pool_info, nullptr, &pool_), "vkCreateCommandPool");

        VkCommandBufferAllocateInfo allocate{};
        allocate.sType = VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO;
        allocate.commandPool = pool_;
        allocate.level = VK_COMMAND_BUFFER_LEVEL_PRIMARY;
        allocate.commandBufferCount = 1;
        check(vkAllocateCommandBuffers(device_, &allocate, &cmd_), "vkAllocateCommandBuffers");

        VkFenceCreateInfo fence_info{};
        fence_info.sType = VK_STRUCTURE_TYPE_FENCE_CREATE_INFO;
        check(vkCreateFence(device_, &fence_info, nullptr, &fence_), "vkCreateFence");
    } catch (...) {
        release();  // a constructor that throws runs no destructor
        throw;
    }
}

FrameCommands::~FrameCommands() { release(); }

void FrameCommands::release() {
    if (fence_) {
        // A failed frame may have left a submission in flight: let it finish before its objects go.
        if (in_flight_) vkWaitForFences(device_, 1, &fence_, VK_TRUE, UINT64_MAX);
        vkDestroyFence(device_, fence_, nullptr);
    }
    if (pool_) vkDestroyCommandPool(device_, pool_, nullptr);  // frees the command buffer
    fence_ = VK_NULL_HANDLE;
    pool_ = VK_NULL_HANDLE;
}

VkCommandBuffer FrameCommands::begin() {
    wait();
    check(vkResetCommandBuffer(cmd_, 0), "vkResetCommandBuffer");
    VkCommandBufferBeginInfo info{};
    info.sType = VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO;
    info.flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT;
    check(vkBeginCommandBuffer(cmd_, &info), "vkBeginCommandBuffer");
    return cmd_;
}

void FrameCommands::submit(VkQueue queue, VkSemaphore wait_semaphore, VkPipelineStageFlags2 wait_stages,
                           VkSemaphore signal) {
    check(vkEndCommandBuffer(cmd_), "vkEndCommandBuffer");
    VkCommandBufferSubmitInfo command{};
    command.sType = VK_STRUCTURE_TYPE_COMMAND_BUFFER_SUBMIT_INFO;
    command.commandBuffer = cmd_;
    VkSemaphoreSubmitInfo wait_info{};
    wait_info.sType = VK_STRUCTURE_TYPE_SEMAPHORE_SUBMIT_INFO;
    wait_info.semaphore = wait_semaphore;
    wait_info.stageMask = wait_stages;
    VkSemaphoreSubmitInfo signal_info{};
    signal_info.sType = VK_STRUCTURE_TYPE_SEMAPHORE_SUBMIT_INFO;
    signal_info.semaphore = signal;
    signal_info.stageMask = VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT;

    VkSubmitInfo2 submit_info{};
    submit_info.sType = VK_STRUCTURE_TYPE_SUBMIT_INFO_2;
    submit_info.commandBufferInfoCount = 1;
    submit_info.pCommandBufferInfos = &command;
    submit_info.waitSemaphoreInfoCount = wait_semaphore ? 1 : 0;
    submit_info.pWaitSemaphoreInfos = &wait_info;
    submit_info.signalSemaphoreInfoCount = signal ? 1 : 0;
    submit_info.pSignalSemaphoreInfos = &signal_info;
    check(vkQueueSubmit2(queue, 1, &submit_info, fence_), "vkQueueSubmit2");
    in_flight_ = true;
}

void FrameCommands::wait() {
    if (!in_flight_) return;
    check(vkWaitForFences(device_, 1, &fence_, VK_TRUE, UINT64_MAX), "vkWaitForFences");
    check(vkResetFences(device_, 1, &fence_), "vkResetFences");
    in_flight_ = false;
}

}  // namespace embed_host
