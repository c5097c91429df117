#include "engine/vk/check.hpp"

#include "engine/core/errors.hpp"

namespace vkw {

std::string vk_result_name(VkResult result) {
    switch (result) {
#define VKW_RESULT_CASE(r) \
    case r: return #r;
        VKW_RESULT_CASE(VK_SUCCESS)
        VKW_RESULT_CASE(VK_NOT_READY)
        VKW_RESULT_CASE(VK_TIMEOUT)
        VKW_RESULT_CASE(VK_EVENT_SET)
        VKW_RESULT_CASE(VK_EVENT_RESET)
        VKW_RESULT_CASE(VK_INCOMPLETE)
        VKW_RESULT_CASE(VK_SUBOPTIMAL_KHR)
        VKW_RESULT_CASE(VK_ERROR_OUT_OF_HOST_MEMORY)
        VKW_RESULT_CASE(VK_ERROR_OUT_OF_DEVICE_MEMORY)
        VKW_RESULT_CASE(VK_ERROR_INITIALIZATION_FAILED)
        VKW_RESULT_CASE(VK_ERROR_DEVICE_LOST)
        VKW_RESULT_CASE(VK_ERROR_MEMORY_MAP_FAILED)
        VKW_RESULT_CASE(VK_ERROR_LAYER_NOT_PRESENT)
        VKW_RESULT_CASE(VK_ERROR_EXTENSION_NOT_PRESENT)
        VKW_RESULT_CASE(VK_ERROR_FEATURE_NOT_PRESENT)
        VKW_RESULT_CASE(VK_ERROR_INCOMPATIBLE_DRIVER)
        VKW_RESULT_CASE(VK_ERROR_TOO_MANY_OBJECTS)
        VKW_RESULT_CASE(VK_ERROR_FORMAT_NOT_SUPPORTED)
        VKW_RESULT_CASE(VK_ERROR_FRAGMENTED_POOL)
        VKW_RESULT_CASE(VK_ERROR_UNKNOWN)
        VKW_RESULT_CASE(VK_ERROR_OUT_OF_POOL_MEMORY)
        VKW_RESULT_CASE(VK_ERROR_INVALID_EXTERNAL_HANDLE)
        VKW_RESULT_CASE(VK_ERROR_FRAGMENTATION)
        VKW_RESULT_CASE(VK_ERROR_SURFACE_LOST_KHR)
        VKW_RESULT_CASE(VK_ERROR_NATIVE_WINDOW_IN_USE_KHR)
        VKW_RESULT_CASE(VK_ERROR_OUT_OF_DATE_KHR)
        VKW_RESULT_CASE(VK_ERROR_VALIDATION_FAILED_EXT)
#undef VKW_RESULT_CASE
        default: return "VkResult(" + std::to_string(static_cast<int>(result)) + ")";
    }
}

void check_vk(VkResult result, std::string_view call, std::string_view what) {
    if (result == VK_SUCCESS) return;
    std::string message = std::string(call.substr(0, call.find('('))) + " failed: " + vk_result_name(result);
    if (!what.empty()) message += " (" + std::string(what) + ")";
    throw InternalError(message);
}

}  // namespace vkw
