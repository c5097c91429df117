// The host's Vulkan device, lent to vkwater, and what vkwater needs of it.
//
// vkwater records on one queue that does graphics and compute, with Vulkan 1.3's dynamic rendering
// and synchronization2 and the device extension VK_KHR_push_descriptor. A host that creates its
// device asks device_requirements() what to enable and chains the returned features into its
// VkDeviceCreateInfo; it then passes that same chain back in HostDevice::enabled_features, from
// which vkwater reads what it may use (optional features only make some effects faster).
#pragma once

#include <vkwater/status.hpp>

#include <vulkan/vulkan.h>

#include <memory>
#include <vector>

namespace vkwater {

struct HostDevice {
    VkInstance instance = VK_NULL_HANDLE;  // created for Vulkan 1.3 (VkApplicationInfo::apiVersion)
    VkPhysicalDevice physical_device = VK_NULL_HANDLE;
    VkDevice device = VK_NULL_HANDLE;
    VkQueue queue = VK_NULL_HANDLE;  // vkwater submits its uploads here while it creates a world
    uint32_t queue_family = 0;       // must support graphics and compute
    // The VkPhysicalDeviceFeatures2 chain the device was created with (VkDeviceCreateInfo::pNext).
    const VkPhysicalDeviceFeatures2* enabled_features = nullptr;
    // Used for every Vulkan object vkwater creates; null: the driver's allocator.
    const VkAllocationCallbacks* allocator = nullptr;
    // VK_EXT_debug_utils is enabled on the instance: vkwater names its objects and labels its passes.
    bool debug_utils = false;
};

// What to enable on a device for vkwater: the extensions and a feature chain with every feature it
// needs set and every optional one it can use set where `physical_device` supports it. The chain's
// storage lives in this object, which must outlive the device's use by vkwater (HostDevice points
// into it); pass `features()` as VkDeviceCreateInfo::pNext.
class DeviceRequirements {
public:
    explicit DeviceRequirements(VkPhysicalDevice physical_device);
    ~DeviceRequirements();
    DeviceRequirements(const DeviceRequirements&) = delete;
    DeviceRequirements& operator=(const DeviceRequirements&) = delete;

    // Empty when the device can run vkwater; else one line naming what it lacks.
    const Status& supported() const { return status_; }
    const std::vector<const char*>& extensions() const { return extensions_; }
    VkPhysicalDeviceFeatures2* features();
    // The chain's Vulkan 1.2 and 1.3 structures, for a host that turns on more of their features
    // (a structure type may appear only once in a chain, so the host cannot add its own of these).
    VkPhysicalDeviceVulkan12Features& vulkan12_features();
    VkPhysicalDeviceVulkan13Features& vulkan13_features();
    void** host_features_tail();  // the last link's pNext, where a host chains its other structures

private:
    struct Chain;
    std::unique_ptr<Chain> chain_;
    std::vector<const char*> extensions_;
    Status status_;
};

}  // namespace vkwater
