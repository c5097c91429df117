#include "engine/window/swapchain.hpp"

#include "engine/core/errors.hpp"
#include "engine/vk/check.hpp"
#include "engine/vk/context.hpp"

#include <algorithm>
#include <cstdio>

namespace vkw::window {
namespace {

VkPresentModeKHR vk_present_mode(PresentMode mode) {
    switch (mode) {
        case PresentMode::Fifo: return VK_PRESENT_MODE_FIFO_KHR;
        case PresentMode::Mailbox: return VK_PRESENT_MODE_MAILBOX_KHR;
        case PresentMode::Immediate: return VK_PRESENT_MODE_IMMEDIATE_KHR;
    }
    return VK_PRESENT_MODE_FIFO_KHR;
}

VkSurfaceFormatKHR pick_format(VkPhysicalDevice device, VkSurfaceKHR surface) {
    uint32_t count = 0;
    VKW_CHECK(vkGetPhysicalDeviceSurfaceFormatsKHR(device, surface, &count, nullptr), "surface formats");
    std::vector<VkSurfaceFormatKHR> formats(count);
    VKW_CHECK(vkGetPhysicalDeviceSurfaceFormatsKHR(device, surface, &count, formats.data()), "surface formats");
    if (formats.empty()) throw InternalError("the window surface offers no format");
    for (VkFormat wanted :
         {VK_FORMAT_B8G8R8A8_UNORM, VK_FORMAT_R8G8B8A8_UNORM, VK_FORMAT_B8G8R8A8_SRGB, VK_FORMAT_R8G8B8A8_SRGB}) {
        for (const VkSurfaceFormatKHR& format : formats) {
            if (format.format == wanted && format.colorSpace == VK_COLOR_SPACE_SRGB_NONLINEAR_KHR) return format;
        }
    }
    throw InternalError("the window surface offers no 8-bit RGBA/BGRA format in the sRGB colour space");
}

PresentMode pick_mode(VkPhysicalDevice device, VkSurfaceKHR surface, PresentMode wanted) {
    uint32_t count = 0;
    VKW_CHECK(vkGetPhysicalDeviceSurfacePresentModesKHR(device, surface, &count, nullptr), "present modes");
    std::vector<VkPresentModeKHR> modes(count);
    VKW_CHECK(vkGetPhysicalDeviceSurfacePresentModesKHR(device, surface, &count, modes.data()), "present modes");
    if (std::find(modes.begin(), modes.end(), vk_present_mode(wanted)) != modes.end()) return wanted;
    std::fprintf(stderr, "vkwater: present mode %s is not offered by this surface; using fifo\n",
                 present_mode_name(wanted));
    return PresentMode::Fifo;  // every surface supports FIFO
}

}  // namespace

const char* present_mode_name(PresentMode mode) {
    switch (mode) {
        case PresentMode::Fifo: return "fifo";
        case PresentMode::Mailbox: return "mailbox";
        case PresentMode::Immediate: return "immediate";
    }
    return "?";
}

Swapchain::Swapchain(Context& context, VkSurfaceKHR surface, PresentMode wanted)
    : context_(context), surface_(surface) {
    try {
        VkBool32 supported = VK_FALSE;
        VKW_CHECK(vkGetPhysicalDeviceSurfaceSupportKHR(context_.physical_device(), context_.queue_family(), surface_,
                                                       &supported),
                  "surface support");
        if (!supported) {
            throw InternalError("device '" + context_.device_name() +
                                "' cannot present to the window (its queue family " +
                                std::to_string(context_.queue_family()) + " has no present support)");
        }
        format_ = pick_format(context_.physical_device(), surface_);
        mode_ = pick_mode(context_.physical_device(), surface_, wanted);
    } catch (...) {
        vkDestroySurfaceKHR(context_.instance(), surface_, nullptr);
        throw;
    }
}

Swapchain::~Swapchain() {
    vkDeviceWaitIdle(context_.device());
    destroy_views();
    if (swapchain_) vkDestroySwapchainKHR(context_.device(), swapchain_, nullptr);
    vkDestroySurfaceKHR(context_.instance(), surface_, nullptr);
}

void Swapchain::destroy_views() {
    for (VkImageView view : views_) {
        context_.forget_name(view, VK_OBJECT_TYPE_IMAGE_VIEW);
        vkDestroyImageView(context_.device(), view, nullptr);
    }
    views_.clear();
    // The images go with their swapchain, never one by one: their names must be dropped here.
    for (VkImage image : images_) context_.forget_name(image, VK_OBJECT_TYPE_IMAGE);
}

bool Swapchain::encodes_srgb() const {
    return format_.format == VK_FORMAT_B8G8R8A8_SRGB || format_.format == VK_FORMAT_R8G8B8A8_SRGB;
}

void Swapchain::recreate(VkExtent2D size) {
    VkDevice device = context_.device();
    vkDeviceWaitIdle(device);  // the old images may still be rendered to or presented
    VkSurfaceCapabilitiesKHR caps;
    VKW_CHECK(vkGetPhysicalDeviceSurfaceCapabilitiesKHR(context_.physical_device(), surface_, &caps),
              "surface capabilities");
    // X11 reports the window's size as the current extent; 0xFFFFFFFF means "you choose".
    if (caps.currentExtent.width != UINT32_MAX) size = caps.currentExtent;
    extent_ = {std::clamp(size.width, caps.minImageExtent.width, caps.maxImageExtent.width),
               std::clamp(size.height, caps.minImageExtent.height, caps.maxImageExtent.height)};
    // One more than the minimum, so that acquiring never waits for the presentation engine.
    uint32_t count = caps.minImageCount + 1;
    if (caps.maxImageCount > 0) count = std::min(count, caps.maxImageCount);

    VkSwapchainCreateInfoKHR info{VK_STRUCTURE_TYPE_SWAPCHAIN_CREATE_INFO_KHR};
    info.surface = surface_;
    info.minImageCount = count;
    info.imageFormat = format_.format;
    info.imageColorSpace = format_.colorSpace;
    info.imageExtent = extent_;
    info.imageArrayLayers = 1;
    info.imageUsage = VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT;  // the tonemap and the overlay draw into it
    info.imageSharingMode = VK_SHARING_MODE_EXCLUSIVE;
    info.preTransform = caps.currentTransform;
    info.compositeAlpha = VK_COMPOSITE_ALPHA_OPAQUE_BIT_KHR;
    info.presentMode = vk_present_mode(mode_);
    info.clipped = VK_TRUE;
    info.oldSwapchain = swapchain_;
    VkSwapchainKHR created = VK_NULL_HANDLE;
    VKW_CHECK(vkCreateSwapchainKHR(device, &info, nullptr, &created),
              "swapchain " + std::to_string(extent_.width) + "x" + std::to_string(extent_.height));
    destroy_views();
    context_.forget_name(swapchain_, VK_OBJECT_TYPE_SWAPCHAIN_KHR);
    if (swapchain_) vkDestroySwapchainKHR(device, swapchain_, nullptr);
    swapchain_ = created;
    context_.set_name(swapchain_, VK_OBJECT_TYPE_SWAPCHAIN_KHR, "window swapchain");

    VKW_CHECK(vkGetSwapchainImagesKHR(device, swapchain_, &count, nullptr), "swapchain images");
    images_.resize(count);
    VKW_CHECK(vkGetSwapchainImagesKHR(device, swapchain_, &count, images_.data()), "swapchain images");
    for (uint32_t i = 0; i < count; ++i) {
        const std::string name = "swapchain image " + std::to_string(i);
        context_.set_name(images_[i], VK_OBJECT_TYPE_IMAGE, name);
        VkImageViewCreateInfo view_info{VK_STRUCTURE_TYPE_IMAGE_VIEW_CREATE_INFO};
        view_info.image = images_[i];
        view_info.viewType = VK_IMAGE_VIEW_TYPE_2D;
        view_info.format = format_.format;
        view_info.subresourceRange = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 1, 0, 1};
        VkImageView view = VK_NULL_HANDLE;
        VKW_CHECK(vkCreateImageView(device, &view_info, nullptr, &view), name);
        context_.set_name(view, VK_OBJECT_TYPE_IMAGE_VIEW, name);
        views_.push_back(view);
    }
    ++generation_;
}

SwapchainStatus Swapchain::acquire(VkSemaphore acquired, uint32_t& index) {
    const VkResult result =
        vkAcquireNextImageKHR(context_.device(), swapchain_, UINT64_MAX, acquired, VK_NULL_HANDLE, &index);
    if (result == VK_ERROR_OUT_OF_DATE_KHR) return SwapchainStatus::OutOfDate;
    if (result == VK_SUBOPTIMAL_KHR) return SwapchainStatus::Suboptimal;  // acquired: render and present it
    VKW_CHECK(result, "swapchain image");
    return SwapchainStatus::Ok;
}

SwapchainStatus Swapchain::present(VkSemaphore rendered, uint32_t index) {
    VkPresentInfoKHR info{VK_STRUCTURE_TYPE_PRESENT_INFO_KHR};
    info.waitSemaphoreCount = 1;
    info.pWaitSemaphores = &rendered;
    info.swapchainCount = 1;
    info.pSwapchains = &swapchain_;
    info.pImageIndices = &index;
    const VkResult result = vkQueuePresentKHR(context_.queue(), &info);
    if (result == VK_ERROR_OUT_OF_DATE_KHR) return SwapchainStatus::OutOfDate;
    if (result == VK_SUBOPTIMAL_KHR) return SwapchainStatus::Suboptimal;
    VKW_CHECK(result, "present");
    return SwapchainStatus::Ok;
}

}  // namespace vkw::window
