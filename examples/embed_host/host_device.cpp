// HostVulkan (host_device.hpp).
//
// Throughout the sample, Vulkan structures are zeroed with {} and then given their sType:
// `VkInstanceCreateInfo info{VK_STRUCTURE_TYPE_INSTANCE_CREATE_INFO}` means the same, but GCC's -Wextra
// warns about every member it leaves out (-Wmissing-field-initializers), and a host's flags are its own.
#include "host_device.hpp"

#include "errors.hpp"

#include <algorithm>
#include <atomic>
#include <cstdio>
#include <cstring>

namespace embed_host {
namespace {

constexpr const char* kValidationLayer = "VK_LAYER_KHRONOS_validation";

std::atomic<uint32_t> g_validation_messages{0};

// Every warning and error is printed and counted: main() fails the run if any was, so that a
// barrier missing on either side of vkwater's commands cannot pass unnoticed.
VKAPI_ATTR VkBool32 VKAPI_CALL on_validation_message(VkDebugUtilsMessageSeverityFlagBitsEXT severity,
                                                     VkDebugUtilsMessageTypeFlagsEXT,
                                                     const VkDebugUtilsMessengerCallbackDataEXT* data, void*) {
    const bool error = severity & VK_DEBUG_UTILS_MESSAGE_SEVERITY_ERROR_BIT_EXT;
    g_validation_messages.fetch_add(1);
    std::fprintf(stderr, "validation %s: %s\n", error ? "error" : "warning",
                 data && data->pMessage ? data->pMessage : "(no message)");
    return VK_FALSE;  // let the call go on: the run fails at its end, with every message printed
}

bool has_layer(const char* name) {
    uint32_t count = 0;
    vkEnumerateInstanceLayerProperties(&count, nullptr);
    std::vector<VkLayerProperties> layers(count);
    vkEnumerateInstanceLayerProperties(&count, layers.data());
    return std::any_of(layers.begin(), layers.end(),
                       [&](const VkLayerProperties& layer) { return std::strcmp(layer.layerName, name) == 0; });
}

bool has_instance_extension(const char* name) {
    uint32_t count = 0;
    vkEnumerateInstanceExtensionProperties(nullptr, &count, nullptr);
    std::vector<VkExtensionProperties> extensions(count);
    vkEnumerateInstanceExtensionProperties(nullptr, &count, extensions.data());
    return std::any_of(extensions.begin(), extensions.end(),
                       [&](const VkExtensionProperties& e) { return std::strcmp(e.extensionName, name) == 0; });
}

// A queue family that does graphics and compute (vkwater records both on one queue) and, when a
// surface is given, can present to it: the sample submits everything on that one queue.
bool find_queue_family(VkPhysicalDevice physical_device, VkSurfaceKHR surface, uint32_t& family) {
    uint32_t count = 0;
    vkGetPhysicalDeviceQueueFamilyProperties(physical_device, &count, nullptr);
    std::vector<VkQueueFamilyProperties> families(count);
    vkGetPhysicalDeviceQueueFamilyProperties(physical_device, &count, families.data());
    const VkQueueFlags needed = VK_QUEUE_GRAPHICS_BIT | VK_QUEUE_COMPUTE_BIT;
    for (uint32_t i = 0; i < count; ++i) {
        if ((families[i].queueFlags & needed) != needed) continue;
        if (surface != VK_NULL_HANDLE) {
            VkBool32 present = VK_FALSE;
            vkGetPhysicalDeviceSurfaceSupportKHR(physical_device, i, surface, &present);
            if (!present) continue;
        }
        family = i;
        return true;
    }
    return false;
}

// Discrete GPUs first, then integrated, then the rest (lavapipe, a CPU device, last).
int device_rank(VkPhysicalDevice physical_device) {
    VkPhysicalDeviceProperties properties;
    vkGetPhysicalDeviceProperties(physical_device, &properties);
    switch (properties.deviceType) {
        case VK_PHYSICAL_DEVICE_TYPE_DISCRETE_GPU: return 0;
        case VK_PHYSICAL_DEVICE_TYPE_INTEGRATED_GPU: return 1;
        default: return 2;
    }
}

}  // namespace

uint32_t validation_message_count() { return g_validation_messages.load(); }

HostVulkan::HostVulkan(const HostOptions& options) : options_(options) {
    try {
        create_instance();
    } catch (...) {
        release();  // a constructor that throws runs no destructor
        throw;
    }
}

HostVulkan::~HostVulkan() { release(); }

void HostVulkan::create_instance() {
    uint32_t loader_version = 0;
    if (vkEnumerateInstanceVersion(&loader_version) != VK_SUCCESS || loader_version < VK_API_VERSION_1_3) {
        throw HostError("the Vulkan loader does not support Vulkan 1.3 (vkwater needs it)", kExitInternal);
    }
    std::vector<const char*> extensions = options_.instance_extensions;
    std::vector<const char*> layers;
    // Debug utils whenever the loader has it: vkwater then names its objects and labels its passes,
    // which makes validation messages and captures readable.
    debug_utils_ = has_instance_extension(VK_EXT_DEBUG_UTILS_EXTENSION_NAME);
    if (debug_utils_) extensions.push_back(VK_EXT_DEBUG_UTILS_EXTENSION_NAME);
    if (options_.validation) {
        if (!has_layer(kValidationLayer)) {
            throw HostError(std::string("--validation needs ") + kValidationLayer +
                                ", which is not installed (Debian: vulkan-validationlayers)",
                            kExitInternal);
        }
        if (!debug_utils_)
            throw HostError("--validation needs VK_EXT_debug_utils, which the loader lacks", kExitInternal);
        layers.push_back(kValidationLayer);
    }

    VkApplicationInfo app{};
    app.sType = VK_STRUCTURE_TYPE_APPLICATION_INFO;
    app.pApplicationName = "vkwater embed_host";
    app.apiVersion = VK_API_VERSION_1_3;  // vkwater::HostDevice::instance must be a 1.3 instance

    // Synchronization validation is off by default in the layer; it is the check that matters most
    // where two engines share a command buffer.
    const VkValidationFeatureEnableEXT enabled[] = {VK_VALIDATION_FEATURE_ENABLE_SYNCHRONIZATION_VALIDATION_EXT};
    VkValidationFeaturesEXT features{};
    features.sType = VK_STRUCTURE_TYPE_VALIDATION_FEATURES_EXT;
    features.enabledValidationFeatureCount = 1;
    features.pEnabledValidationFeatures = enabled;

    // Chained into the instance's creation as well, so that vkCreateInstance and vkDestroyInstance
    // themselves are checked.
    VkDebugUtilsMessengerCreateInfoEXT messenger{};
    messenger.sType = VK_STRUCTURE_TYPE_DEBUG_UTILS_MESSENGER_CREATE_INFO_EXT;
    messenger.messageSeverity =
        VK_DEBUG_UTILS_MESSAGE_SEVERITY_WARNING_BIT_EXT | VK_DEBUG_UTILS_MESSAGE_SEVERITY_ERROR_BIT_EXT;
    messenger.messageType = VK_DEBUG_UTILS_MESSAGE_TYPE_GENERAL_BIT_EXT |
                            VK_DEBUG_UTILS_MESSAGE_TYPE_VALIDATION_BIT_EXT |
                            VK_DEBUG_UTILS_MESSAGE_TYPE_PERFORMANCE_BIT_EXT;
    messenger.pfnUserCallback = on_validation_message;
    messenger.pNext = &features;

    VkInstanceCreateInfo info{};
    info.sType = VK_STRUCTURE_TYPE_INSTANCE_CREATE_INFO;
    info.pApplicationInfo = &app;
    info.enabledLayerCount = static_cast<uint32_t>(layers.size());
    info.ppEnabledLayerNames = layers.data();
    info.enabledExtensionCount = static_cast<uint32_t>(extensions.size());
    info.ppEnabledExtensionNames = extensions.data();
    if (options_.validation) info.pNext = &messenger;
    check(vkCreateInstance(&info, nullptr, &instance_), "vkCreateInstance (Vulkan 1.3)");

    if (options_.validation) {
        messenger.pNext = nullptr;
        auto create = reinterpret_cast<PFN_vkCreateDebugUtilsMessengerEXT>(
            vkGetInstanceProcAddr(instance_, "vkCreateDebugUtilsMessengerEXT"));
        if (!create) throw HostError("vkCreateDebugUtilsMessengerEXT is missing", kExitInternal);
        check(create(instance_, &messenger, nullptr, &messenger_), "vkCreateDebugUtilsMessengerEXT");
    }
}

void HostVulkan::create_device(VkSurfaceKHR surface) {
    uint32_t count = 0;
    check(vkEnumeratePhysicalDevices(instance_, &count, nullptr), "vkEnumeratePhysicalDevices");
    std::vector<VkPhysicalDevice> devices(count);
    check(vkEnumeratePhysicalDevices(instance_, &count, devices.data()), "vkEnumeratePhysicalDevices");
    std::stable_sort(devices.begin(), devices.end(),
                     [](VkPhysicalDevice a, VkPhysicalDevice b) { return device_rank(a) < device_rank(b); });

    // The first device vkwater can run on; vkwater's own word on the last one it cannot.
    vkwater::Status why_not{vkwater::ErrorKind::Internal, "no Vulkan device found"};
    for (VkPhysicalDevice candidate : devices) {
        auto requirements = std::make_unique<vkwater::DeviceRequirements>(candidate);
        if (!requirements->supported()) {
            why_not = requirements->supported();
            continue;
        }
        uint32_t family = 0;
        if (!find_queue_family(candidate, surface, family)) {
            why_not = {vkwater::ErrorKind::Internal,
                       "no queue family does graphics, compute" + std::string(surface ? " and presents" : "")};
            continue;
        }
        physical_device_ = candidate;
        queue_family_ = family;
        requirements_ = std::move(requirements);
        break;
    }
    if (physical_device_ == VK_NULL_HANDLE) check(why_not);

    std::vector<const char*> extensions = requirements_->extensions();
    extensions.insert(extensions.end(), options_.device_extensions.begin(), options_.device_extensions.end());

    const float priority = 1.0f;
    VkDeviceQueueCreateInfo queue_info{};
    queue_info.sType = VK_STRUCTURE_TYPE_DEVICE_QUEUE_CREATE_INFO;
    queue_info.queueFamilyIndex = queue_family_;
    queue_info.queueCount = 1;
    queue_info.pQueuePriorities = &priority;

    VkDeviceCreateInfo info{};
    info.sType = VK_STRUCTURE_TYPE_DEVICE_CREATE_INFO;
    // vkwater's feature chain (VkPhysicalDeviceFeatures2 -> 1.2 -> 1.3) is the device's whole feature
    // request; a host that needs more sets it in these structures or chains its own behind
    // host_features_tail(). pEnabledFeatures must stay null with a Features2 chain.
    info.pNext = requirements_->features();
    info.queueCreateInfoCount = 1;
    info.pQueueCreateInfos = &queue_info;
    info.enabledExtensionCount = static_cast<uint32_t>(extensions.size());
    info.ppEnabledExtensionNames = extensions.data();
    check(vkCreateDevice(physical_device_, &info, nullptr, &device_), "vkCreateDevice");
    vkGetDeviceQueue(device_, queue_family_, 0, &queue_);
}

vkwater::HostDevice HostVulkan::lend() const {
    vkwater::HostDevice lent;
    lent.instance = instance_;
    lent.physical_device = physical_device_;
    lent.device = device_;
    lent.queue = queue_;
    lent.queue_family = queue_family_;
    lent.enabled_features = requirements_ ? requirements_->features() : nullptr;
    lent.debug_utils = debug_utils_;
    return lent;
}

std::string HostVulkan::device_name() const {
    if (physical_device_ == VK_NULL_HANDLE) return "(none)";
    VkPhysicalDeviceProperties properties;
    vkGetPhysicalDeviceProperties(physical_device_, &properties);
    return properties.deviceName;
}

void HostVulkan::release() {
    if (device_) {
        vkDeviceWaitIdle(device_);
        vkDestroyDevice(device_, nullptr);
        device_ = VK_NULL_HANDLE;
    }
    if (messenger_) {
        auto destroy = reinterpret_cast<PFN_vkDestroyDebugUtilsMessengerEXT>(
            vkGetInstanceProcAddr(instance_, "vkDestroyDebugUtilsMessengerEXT"));
        if (destroy) destroy(instance_, messenger_, nullptr);
        messenger_ = VK_NULL_HANDLE;
    }
    if (instance_) {
        vkDestroyInstance(instance_, nullptr);
        instance_ = VK_NULL_HANDLE;
    }
}

}  // namespace embed_host
