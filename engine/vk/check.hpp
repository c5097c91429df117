// Error checking for Vulkan calls: every failing call becomes an InternalError that
// names the call, the VkResult and the object it was about.
#pragma once

#include <vulkan/vulkan.h>

#include <string>
#include <string_view>

namespace vkw {

// "VK_ERROR_OUT_OF_DEVICE_MEMORY" for VK_ERROR_OUT_OF_DEVICE_MEMORY; the number otherwise.
std::string vk_result_name(VkResult result);

// Throws InternalError("<call> failed: <VkResult name> (<what>)") unless result is VK_SUCCESS.
// Not an assert: it stays in release builds.
void check_vk(VkResult result, std::string_view call, std::string_view what = {});

}  // namespace vkw

// VKW_CHECK(vkCreateImage(...), "image 'hdr'") - the call's text becomes part of the message.
#define VKW_CHECK(call, what) ::vkw::check_vk((call), #call, (what))
