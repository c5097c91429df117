// The device features vkwater enables: the required ones (dynamic rendering, synchronization2) and
// every optional one it can use where the device supports it. One list for the device vkw::Context
// creates and for the one a host creates for the embedding library (include/vkwater/device.hpp).
#pragma once

#include <vulkan/vulkan.h>

#include <string>

namespace vkw {

// A VkPhysicalDeviceFeatures2 chain (features -> 1.2 -> 1.3); not copyable: it points into itself.
struct DeviceFeatureChain {
    VkPhysicalDeviceFeatures2 features{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_FEATURES_2};
    VkPhysicalDeviceVulkan12Features features12{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_2_FEATURES};
    VkPhysicalDeviceVulkan13Features features13{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_3_FEATURES};

    DeviceFeatureChain();
    DeviceFeatureChain(const DeviceFeatureChain&) = delete;
    DeviceFeatureChain& operator=(const DeviceFeatureChain&) = delete;
};

// Fills `request` with what to enable on `physical_device`. Returns an empty string when the device
// can run vkwater, else what it lacks.
std::string request_device_features(VkPhysicalDevice physical_device, DeviceFeatureChain& request);

}  // namespace vkw
