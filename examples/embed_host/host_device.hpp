// The host's own Vulkan instance, device and queue, created with what vkwater asks of them
// (vkwater::DeviceRequirements) and lent to it as a vkwater::HostDevice. The host owns them: vkwater
// destroys nothing of them.
#pragma once

#include <vkwater/device.hpp>

#include <vulkan/vulkan.h>

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

namespace embed_host {

struct HostOptions {
    // The Khronos validation layer with synchronization validation, which checks the barriers
    // between the host's commands and vkwater's as well as each side's own.
    bool validation = false;
    std::vector<const char*> instance_extensions;  // the host's own, e.g. GLFW's surface extensions
    std::vector<const char*> device_extensions;    // the host's own, e.g. VK_KHR_swapchain
};

// The validation warnings and errors printed so far by any HostVulkan of this process. It counts on
// after a HostVulkan is destroyed, so that what the layer reports at vkDestroyDevice and
// vkDestroyInstance (objects left alive) counts too.
uint32_t validation_message_count();

class HostVulkan {
public:
    // Creates the instance (Vulkan 1.3) and, with validation, its debug messenger.
    explicit HostVulkan(const HostOptions& options);
    ~HostVulkan();
    HostVulkan(const HostVulkan&) = delete;
    HostVulkan& operator=(const HostVulkan&) = delete;

    // Picks a device vkwater can run on that has a graphics and compute queue family (which can also
    // present to `surface` when one is given) and creates it with vkwater's extensions and features.
    void create_device(VkSurfaceKHR surface = VK_NULL_HANDLE);

    // What vkwater::World::load borrows; valid once create_device() has run.
    vkwater::HostDevice lend() const;

    VkInstance instance() const { return instance_; }
    VkPhysicalDevice physical_device() const { return physical_device_; }
    VkDevice device() const { return device_; }
    VkQueue queue() const { return queue_; }
    uint32_t queue_family() const { return queue_family_; }
    std::string device_name() const;

private:
    void create_instance();
    void release();

    HostOptions options_;
    bool debug_utils_ = false;
    VkInstance instance_ = VK_NULL_HANDLE;
    VkDebugUtilsMessengerEXT messenger_ = VK_NULL_HANDLE;
    VkPhysicalDevice physical_device_ = VK_NULL_HANDLE;
    VkDevice device_ = VK_NULL_HANDLE;
    VkQueue queue_ = VK_NULL_HANDLE;
    uint32_t queue_family_ = 0;
    // The feature chain the device was created with: vkwater reads what it may use from it
    // (HostDevice::enabled_features), so it lives as long as the device.
    std::unique_ptr<vkwater::DeviceRequirements> requirements_;
};

}  // namespace embed_host
