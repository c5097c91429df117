// DeviceRequirements (include/vkwater/device.hpp): the features vkw::Context enables on a device it
// creates itself (engine/vk/device_features.hpp), and the extension it binds resources with.
#include <vkwater/device.hpp>

#include "engine/vk/device_features.hpp"

#include <algorithm>
#include <cstring>
#include <string>

namespace vkwater {

struct DeviceRequirements::Chain : vkw::DeviceFeatureChain {};

namespace {

bool has_device_extension(VkPhysicalDevice physical_device, const char* name) {
    uint32_t count = 0;
    vkEnumerateDeviceExtensionProperties(physical_device, nullptr, &count, nullptr);
    std::vector<VkExtensionProperties> extensions(count);
    vkEnumerateDeviceExtensionProperties(physical_device, nullptr, &count, extensions.data());
    return std::any_of(extensions.begin(), extensions.end(),
                       [&](const VkExtensionProperties& e) { return std::strcmp(e.extensionName, name) == 0; });
}

}  // namespace

DeviceRequirements::DeviceRequirements(VkPhysicalDevice physical_device)
    : chain_(std::make_unique<Chain>()), extensions_{VK_KHR_PUSH_DESCRIPTOR_EXTENSION_NAME} {
    VkPhysicalDeviceProperties properties;
    vkGetPhysicalDeviceProperties(physical_device, &properties);
    const std::string device = "device '" + std::string(properties.deviceName) + "'";
    if (properties.apiVersion < VK_API_VERSION_1_3) {
        status_ = {ErrorKind::Internal, device + " is not a Vulkan 1.3 device"};
        return;
    }
    if (const std::string lacking = vkw::request_device_features(physical_device, *chain_); !lacking.empty()) {
        status_ = {ErrorKind::Internal, device + " lacks " + lacking};
        return;
    }
    if (!has_device_extension(physical_device, VK_KHR_PUSH_DESCRIPTOR_EXTENSION_NAME)) {
        status_ = {ErrorKind::Internal, device + " lacks " VK_KHR_PUSH_DESCRIPTOR_EXTENSION_NAME};
    }
}

DeviceRequirements::~DeviceRequirements() = default;

VkPhysicalDeviceFeatures2* DeviceRequirements::features() { return &chain_->features; }

VkPhysicalDeviceVulkan12Features& DeviceRequirements::vulkan12_features() { return chain_->features12; }

VkPhysicalDeviceVulkan13Features& DeviceRequirements::vulkan13_features() { return chain_->features13; }

void** DeviceRequirements::host_features_tail() { return &chain_->features13.pNext; }

}  // namespace vkwater
