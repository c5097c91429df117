// request_device_features (device_features.hpp).
#include "engine/vk/device_features.hpp"

namespace vkw {

DeviceFeatureChain::DeviceFeatureChain() {
    features.pNext = &features12;
    features12.pNext = &features13;
}

std::string request_device_features(VkPhysicalDevice physical_device, DeviceFeatureChain& request) {
    DeviceFeatureChain supported;
    vkGetPhysicalDeviceFeatures2(physical_device, &supported.features);
    if (!supported.features13.dynamicRendering || !supported.features13.synchronization2) {
        return "dynamic rendering or synchronization2 (Vulkan 1.3)";
    }
    request.features13.dynamicRendering = VK_TRUE;
    request.features13.synchronization2 = VK_TRUE;
    // glslang's vulkan1.3 target declares compute local sizes with LocalSizeId, which
    // needs maintenance4 (a feature every Vulkan 1.3 device has).
    request.features13.maintenance4 = supported.features13.maintenance4;
    // Optional: each makes an effect possible or faster, and the passes read back which were enabled
    // (Context::features): the caustic photons' 64-bit atomics, host-reset timestamp queries,
    // depth clamp for the shadow map, doubles and 64-bit integers, wide godray lines, wireframes.
    request.features12.shaderBufferInt64Atomics = supported.features12.shaderBufferInt64Atomics;
    request.features12.shaderSharedInt64Atomics = supported.features12.shaderSharedInt64Atomics;
    request.features12.hostQueryReset = supported.features12.hostQueryReset;
    request.features.features.depthClamp = supported.features.features.depthClamp;
    request.features.features.shaderFloat64 = supported.features.features.shaderFloat64;
    request.features.features.shaderInt64 = supported.features.features.shaderInt64;
    request.features.features.wideLines = supported.features.features.wideLines;
    request.features.features.fillModeNonSolid = supported.features.features.fillModeNonSolid;
    return {};
}

}  // namespace vkw
