#include "engine/window/frames_in_flight.hpp"

#include "engine/vk/check.hpp"
#include "engine/vk/context.hpp"

#include <string>

namespace vkw::window {
namespace {

VkSemaphore make_semaphore(const Context& context, const std::string& name) {
    VkSemaphoreCreateInfo info{VK_STRUCTURE_TYPE_SEMAPHORE_CREATE_INFO};
    VkSemaphore semaphore = VK_NULL_HANDLE;
    VKW_CHECK(vkCreateSemaphore(context.device(), &info, nullptr, &semaphore), name);
    context.set_name(semaphore, VK_OBJECT_TYPE_SEMAPHORE, name);
    return semaphore;
}

}  // namespace

FramesInFlight::FramesInFlight(Context& context) : context_(context) {
    VkDevice device = context_.device();
    for (uint32_t i = 0; i < kSlots; ++i) {
        Slot& slot = slots_[i];
        const std::string name = "frame slot " + std::to_string(i);
        VkCommandPoolCreateInfo pool_info{VK_STRUCTURE_TYPE_COMMAND_POOL_CREATE_INFO};
        pool_info.flags = VK_COMMAND_POOL_CREATE_TRANSIENT_BIT;
        pool_info.queueFamilyIndex = context_.queue_family();
        VKW_CHECK(vkCreateCommandPool(device, &pool_info, nullptr, &slot.pool), name);
        context_.set_name(slot.pool, VK_OBJECT_TYPE_COMMAND_POOL, name);
        VkCommandBufferAllocateInfo alloc{VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO};
        alloc.commandPool = slot.pool;
        alloc.level = VK_COMMAND_BUFFER_LEVEL_PRIMARY;
        alloc.commandBufferCount = 1;
        VKW_CHECK(vkAllocateCommandBuffers(device, &alloc, &slot.cmd), name);
        context_.set_name(slot.cmd, VK_OBJECT_TYPE_COMMAND_BUFFER, name);
        VkFenceCreateInfo fence_info{VK_STRUCTURE_TYPE_FENCE_CREATE_INFO};
        fence_info.flags = VK_FENCE_CREATE_SIGNALED_BIT;  // a slot that never ran is free
        VKW_CHECK(vkCreateFence(device, &fence_info, nullptr, &slot.done), name);
        context_.set_name(slot.done, VK_OBJECT_TYPE_FENCE, name + " done");
        slot.acquired = make_semaphore(context_, name + " image acquired");
        slot.chain = make_semaphore(context_, name + " finished (chain)");
    }
}

FramesInFlight::~FramesInFlight() {
    VkDevice device = context_.device();
    vkDeviceWaitIdle(device);
    for (VkSemaphore semaphore : rendered_) vkDestroySemaphore(device, semaphore, nullptr);
    for (Slot& slot : slots_) {
        vkDestroySemaphore(device, slot.chain, nullptr);
        vkDestroySemaphore(device, slot.acquired, nullptr);
        vkDestroyFence(device, slot.done, nullptr);
        vkDestroyCommandPool(device, slot.pool, nullptr);  // frees the command buffer
    }
}

FramesInFlight::Slot& FramesInFlight::next_slot() {
    Slot& slot = slots_[current_];
    VKW_CHECK(vkWaitForFences(context_.device(), 1, &slot.done, VK_TRUE, UINT64_MAX), "frame slot fence");
    VKW_CHECK(vkResetCommandPool(context_.device(), slot.pool, 0), "frame slot command pool");
    return slot;
}

void FramesInFlight::set_image_count(uint32_t count) {
    for (VkSemaphore semaphore : rendered_) {
        context_.forget_name(semaphore, VK_OBJECT_TYPE_SEMAPHORE);  // made again at every resize
        vkDestroySemaphore(context_.device(), semaphore, nullptr);
    }
    rendered_.clear();
    for (uint32_t i = 0; i < count; ++i) {
        rendered_.push_back(make_semaphore(context_, "swapchain image " + std::to_string(i) + " rendered"));
    }
}

void FramesInFlight::begin(Slot& slot) {
    VkCommandBufferBeginInfo begin{VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO};
    begin.flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT;
    VKW_CHECK(vkBeginCommandBuffer(slot.cmd, &begin), "frame command buffer");
}

void FramesInFlight::submit(Slot& slot, uint32_t image) {
    VKW_CHECK(vkEndCommandBuffer(slot.cmd), "frame command buffer");
    // The acquired image is first written as a colour attachment: the present graph's first
    // barrier on it waits in that stage, which this wait chains to.
    std::vector<VkSemaphoreSubmitInfo> waits;
    VkSemaphoreSubmitInfo acquired{VK_STRUCTURE_TYPE_SEMAPHORE_SUBMIT_INFO};
    acquired.semaphore = slot.acquired;
    acquired.stageMask = VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT;
    waits.push_back(acquired);
    if (pending_chain_) {
        // Everything of this frame waits for everything of the last one.
        VkSemaphoreSubmitInfo previous{VK_STRUCTURE_TYPE_SEMAPHORE_SUBMIT_INFO};
        previous.semaphore = pending_chain_;
        previous.stageMask = VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT;
        waits.push_back(previous);
    }
    std::array<VkSemaphoreSubmitInfo, 2> signals{};
    signals[0] = {VK_STRUCTURE_TYPE_SEMAPHORE_SUBMIT_INFO};
    signals[0].semaphore = rendered_[image];
    signals[0].stageMask = VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT;
    signals[1] = signals[0];
    signals[1].semaphore = slot.chain;

    VkCommandBufferSubmitInfo cmd_info{VK_STRUCTURE_TYPE_COMMAND_BUFFER_SUBMIT_INFO};
    cmd_info.commandBuffer = slot.cmd;
    VkSubmitInfo2 submit{VK_STRUCTURE_TYPE_SUBMIT_INFO_2};
    submit.waitSemaphoreInfoCount = static_cast<uint32_t>(waits.size());
    submit.pWaitSemaphoreInfos = waits.data();
    submit.commandBufferInfoCount = 1;
    submit.pCommandBufferInfos = &cmd_info;
    submit.signalSemaphoreInfoCount = static_cast<uint32_t>(signals.size());
    submit.pSignalSemaphoreInfos = signals.data();
    VKW_CHECK(vkResetFences(context_.device(), 1, &slot.done), "frame slot fence");
    VKW_CHECK(vkQueueSubmit2(context_.queue(), 1, &submit, slot.done), "frame submission");
    pending_chain_ = slot.chain;
    current_ = (current_ + 1) % kSlots;
}

void FramesInFlight::wait_all() {
    std::array<VkFence, kSlots> fences;
    for (uint32_t i = 0; i < kSlots; ++i) fences[i] = slots_[i].done;
    VKW_CHECK(vkWaitForFences(context_.device(), kSlots, fences.data(), VK_TRUE, UINT64_MAX), "frame slot fences");
}

}  // namespace vkw::window
