#include "engine/vk/context.hpp"

#include "engine/core/errors.hpp"
#include "engine/vk/check.hpp"
#include "engine/vk/device_features.hpp"

#include <algorithm>
#include <cstring>

namespace vkw {
namespace {

constexpr const char* kValidationLayer = "VK_LAYER_KHRONOS_validation";

bool is_accepted_warning(const char* message_id) {
    if (message_id == nullptr) return false;
    return std::any_of(kAcceptedPerformanceWarnings.begin(), kAcceptedPerformanceWarnings.end(),
                       [&](const AcceptedWarning& w) { return std::strcmp(w.message_id, message_id) == 0; });
}

VKAPI_ATTR VkBool32 VKAPI_CALL on_validation_message(VkDebugUtilsMessageSeverityFlagBitsEXT severity,
                                                     VkDebugUtilsMessageTypeFlagsEXT type,
                                                     const VkDebugUtilsMessengerCallbackDataEXT* data, void* user) {
    auto* context = static_cast<Context*>(user);
    const bool error_or_warning =
        severity & (VK_DEBUG_UTILS_MESSAGE_SEVERITY_ERROR_BIT_EXT | VK_DEBUG_UTILS_MESSAGE_SEVERITY_WARNING_BIT_EXT);
    if (!error_or_warning) return VK_FALSE;
    std::string text = std::string("validation ") +
                       ((severity & VK_DEBUG_UTILS_MESSAGE_SEVERITY_ERROR_BIT_EXT) ? "error" : "warning") + ": " +
                       (data->pMessage ? data->pMessage : "");
    const bool performance = type & VK_DEBUG_UTILS_MESSAGE_TYPE_PERFORMANCE_BIT_EXT;
    if (performance && is_accepted_warning(data->pMessageIdName)) {
        context->validation_log().record_accepted(std::move(text));
    } else {
        context->validation_log().record_failure(std::move(text));
    }
    return VK_FALSE;  // never abort the call: vkwater reports and fails after the fact
}

bool has_layer(const char* name) {
    uint32_t count = 0;
    vkEnumerateInstanceLayerProperties(&count, nullptr);
    std::vector<VkLayerProperties> layers(count);
    vkEnumerateInstanceLayerProperties(&count, layers.data());
    return std::any_of(layers.begin(), layers.end(),
                       [&](const VkLayerProperties& l) { return std::strcmp(l.layerName, name) == 0; });
}

bool has_instance_extension(const char* name) {
    uint32_t count = 0;
    vkEnumerateInstanceExtensionProperties(nullptr, &count, nullptr);
    std::vector<VkExtensionProperties> extensions(count);
    vkEnumerateInstanceExtensionProperties(nullptr, &count, extensions.data());
    return std::any_of(extensions.begin(), extensions.end(),
                       [&](const VkExtensionProperties& e) { return std::strcmp(e.extensionName, name) == 0; });
}

int device_type_rank(VkPhysicalDeviceType type) {
    switch (type) {
        case VK_PHYSICAL_DEVICE_TYPE_DISCRETE_GPU: return 0;
        case VK_PHYSICAL_DEVICE_TYPE_INTEGRATED_GPU: return 1;
        case VK_PHYSICAL_DEVICE_TYPE_VIRTUAL_GPU: return 2;
        case VK_PHYSICAL_DEVICE_TYPE_CPU: return 3;
        default: return 4;
    }
}

std::vector<VkPhysicalDevice> enumerate_devices(VkInstance instance) {
    uint32_t count = 0;
    VkResult result = vkEnumeratePhysicalDevices(instance, &count, nullptr);
    if (result != VK_SUCCESS && result != VK_INCOMPLETE) count = 0;
    std::vector<VkPhysicalDevice> devices(count);
    if (count > 0) vkEnumeratePhysicalDevices(instance, &count, devices.data());
    return devices;
}

constexpr const char* kNoDeviceHelp =
    "install a Vulkan 1.3 driver (Debian: mesa-vulkan-drivers provides the lavapipe software device; "
    "tools/install-deps.sh installs it)";

}  // namespace

Context::Context(const ContextOptions& options)
    : validation_(options.validation),
      validation_log_(std::make_shared<ValidationLog>(options.print_validation_messages)) {
    try {
        create_instance(options);
        pick_physical_device(options.device_name);
        create_device(options.swapchain);
    } catch (...) {
        release();  // the destructor does not run for a constructor that throws
        throw;
    }
}

Context::Context(const BorrowedDevice& host)
    : borrowed_(true), allocator_(host.allocator), validation_log_(std::make_shared<ValidationLog>(false)) {
    if (!host.instance || !host.physical_device || !host.device || !host.queue) {
        throw InternalError("the host's device: instance, physical device, device and queue must all be given");
    }
    if (!host.enabled_features) {
        throw InternalError("the host's device: enabled_features must be the feature chain it was created with");
    }
    instance_ = host.instance;
    physical_device_ = host.physical_device;
    device_ = host.device;
    queue_ = host.queue;
    queue_family_ = host.queue_family;
    vkGetPhysicalDeviceProperties(physical_device_, &properties_);
    vkGetPhysicalDeviceMemoryProperties(physical_device_, &memory_properties_);
    try {
        if (properties_.apiVersion < VK_API_VERSION_1_3) {
            throw InternalError("the host's device '" + device_name() + "' is not a Vulkan 1.3 device");
        }
        uint32_t family_count = 0;
        vkGetPhysicalDeviceQueueFamilyProperties(physical_device_, &family_count, nullptr);
        std::vector<VkQueueFamilyProperties> families(family_count);
        vkGetPhysicalDeviceQueueFamilyProperties(physical_device_, &family_count, families.data());
        const VkQueueFlags needed = VK_QUEUE_GRAPHICS_BIT | VK_QUEUE_COMPUTE_BIT;
        if (queue_family_ >= family_count || (families[queue_family_].queueFlags & needed) != needed) {
            throw InternalError("the host's queue family " + std::to_string(queue_family_) + " on '" + device_name() +
                                "' does not do both graphics and compute");
        }
        read_enabled_features(*host.enabled_features);
        load_device_functions();
        if (host.debug_utils) load_debug_utils();
        create_command_pool();
    } catch (...) {
        release();
        throw;
    }
}

Context::~Context() { release(); }

void Context::release() {
    if (device_) {
        vkDeviceWaitIdle(device_);
        if (command_pool_) vkDestroyCommandPool(device_, command_pool_, allocator_);
        if (!borrowed_) vkDestroyDevice(device_, nullptr);
        device_ = VK_NULL_HANDLE;
        command_pool_ = VK_NULL_HANDLE;
    }
    if (borrowed_) {
        instance_ = VK_NULL_HANDLE;  // the host's
        return;
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

void Context::create_instance(const ContextOptions& options) {
    uint32_t loader_version = 0;
    if (vkEnumerateInstanceVersion(&loader_version) != VK_SUCCESS || loader_version < VK_API_VERSION_1_3) {
        throw InternalError("the Vulkan loader does not support Vulkan 1.3; " + std::string(kNoDeviceHelp));
    }
    std::vector<const char*> layers;
    std::vector<const char*> extensions;
    for (const std::string& extension : options.instance_extensions) extensions.push_back(extension.c_str());
    const bool debug_utils = has_instance_extension(VK_EXT_DEBUG_UTILS_EXTENSION_NAME);
    if (debug_utils) extensions.push_back(VK_EXT_DEBUG_UTILS_EXTENSION_NAME);
    if (validation_) {
        if (!has_layer(kValidationLayer)) {
            throw InternalError(std::string("--validation needs the layer ") + kValidationLayer +
                                ", which is not installed (Debian: vulkan-validationlayers)");
        }
        if (!debug_utils) throw InternalError("--validation needs VK_EXT_debug_utils, which the loader lacks");
        layers.push_back(kValidationLayer);
    }

    VkApplicationInfo app{VK_STRUCTURE_TYPE_APPLICATION_INFO};
    app.pApplicationName = "vkwater";
    app.pEngineName = "vkwater";
    app.apiVersion = VK_API_VERSION_1_3;

    // Synchronization validation is off by default in the layer; vkwater always wants it.
    VkValidationFeatureEnableEXT enabled_checks[] = {VK_VALIDATION_FEATURE_ENABLE_SYNCHRONIZATION_VALIDATION_EXT};
    VkValidationFeaturesEXT validation_features{VK_STRUCTURE_TYPE_VALIDATION_FEATURES_EXT};
    validation_features.enabledValidationFeatureCount = 1;
    validation_features.pEnabledValidationFeatures = enabled_checks;

    // The messenger is also chained into instance creation so that messages from
    // vkCreateInstance/vkDestroyInstance themselves are caught.
    VkDebugUtilsMessengerCreateInfoEXT messenger_info{VK_STRUCTURE_TYPE_DEBUG_UTILS_MESSENGER_CREATE_INFO_EXT};
    messenger_info.messageSeverity =
        VK_DEBUG_UTILS_MESSAGE_SEVERITY_WARNING_BIT_EXT | VK_DEBUG_UTILS_MESSAGE_SEVERITY_ERROR_BIT_EXT;
    messenger_info.messageType = VK_DEBUG_UTILS_MESSAGE_TYPE_GENERAL_BIT_EXT |
                                 VK_DEBUG_UTILS_MESSAGE_TYPE_VALIDATION_BIT_EXT |
                                 VK_DEBUG_UTILS_MESSAGE_TYPE_PERFORMANCE_BIT_EXT;
    messenger_info.pfnUserCallback = on_validation_message;
    messenger_info.pUserData = this;
    messenger_info.pNext = &validation_features;

    VkInstanceCreateInfo info{VK_STRUCTURE_TYPE_INSTANCE_CREATE_INFO};
    info.pApplicationInfo = &app;
    info.enabledLayerCount = static_cast<uint32_t>(layers.size());
    info.ppEnabledLayerNames = layers.data();
    info.enabledExtensionCount = static_cast<uint32_t>(extensions.size());
    info.ppEnabledExtensionNames = extensions.data();
    if (validation_) info.pNext = &messenger_info;
    VkResult result = vkCreateInstance(&info, nullptr, &instance_);
    if (result == VK_ERROR_INCOMPATIBLE_DRIVER) {
        throw InternalError("no Vulkan 1.3 driver found; " + std::string(kNoDeviceHelp));
    }
    VKW_CHECK(result, "instance");

    if (validation_) {
        messenger_info.pNext = nullptr;
        auto create = reinterpret_cast<PFN_vkCreateDebugUtilsMessengerEXT>(
            vkGetInstanceProcAddr(instance_, "vkCreateDebugUtilsMessengerEXT"));
        VKW_CHECK(create(instance_, &messenger_info, nullptr, &messenger_), "validation messenger");
    }
    if (debug_utils) load_debug_utils();
}

void Context::load_debug_utils() {
    set_object_name_ = reinterpret_cast<PFN_vkSetDebugUtilsObjectNameEXT>(
        vkGetInstanceProcAddr(instance_, "vkSetDebugUtilsObjectNameEXT"));
    begin_label_ = reinterpret_cast<PFN_vkCmdBeginDebugUtilsLabelEXT>(
        vkGetInstanceProcAddr(instance_, "vkCmdBeginDebugUtilsLabelEXT"));
    end_label_ = reinterpret_cast<PFN_vkCmdEndDebugUtilsLabelEXT>(
        vkGetInstanceProcAddr(instance_, "vkCmdEndDebugUtilsLabelEXT"));
}

void Context::pick_physical_device(const std::string& wanted_name) {
    std::vector<VkPhysicalDevice> devices = enumerate_devices(instance_);
    if (devices.empty()) throw InternalError("no Vulkan device found; " + std::string(kNoDeviceHelp));

    std::vector<VkPhysicalDevice> candidates;
    std::string available;
    for (VkPhysicalDevice device : devices) {
        VkPhysicalDeviceProperties properties;
        vkGetPhysicalDeviceProperties(device, &properties);
        available += (available.empty() ? "'" : ", '") + std::string(properties.deviceName) + "'";
        if (properties.apiVersion < VK_API_VERSION_1_3) continue;
        if (!wanted_name.empty() && std::string(properties.deviceName).find(wanted_name) == std::string::npos) continue;
        candidates.push_back(device);
    }
    if (candidates.empty()) {
        if (!wanted_name.empty()) {
            throw UserError("--device '" + wanted_name + "': no Vulkan 1.3 device matches (available: " + available +
                            ")");
        }
        throw InternalError("no Vulkan 1.3 device found (available: " + available + "); " + kNoDeviceHelp);
    }
    std::stable_sort(candidates.begin(), candidates.end(), [](VkPhysicalDevice a, VkPhysicalDevice b) {
        VkPhysicalDeviceProperties pa, pb;
        vkGetPhysicalDeviceProperties(a, &pa);
        vkGetPhysicalDeviceProperties(b, &pb);
        return device_type_rank(pa.deviceType) < device_type_rank(pb.deviceType);
    });
    physical_device_ = candidates.front();
    vkGetPhysicalDeviceProperties(physical_device_, &properties_);
    vkGetPhysicalDeviceMemoryProperties(physical_device_, &memory_properties_);
}

void Context::create_device(bool swapchain) {
    uint32_t family_count = 0;
    vkGetPhysicalDeviceQueueFamilyProperties(physical_device_, &family_count, nullptr);
    std::vector<VkQueueFamilyProperties> families(family_count);
    vkGetPhysicalDeviceQueueFamilyProperties(physical_device_, &family_count, families.data());
    // vkwater records everything on one queue that does graphics and compute (lavapipe has exactly one).
    const VkQueueFlags needed = VK_QUEUE_GRAPHICS_BIT | VK_QUEUE_COMPUTE_BIT;
    auto family = std::find_if(families.begin(), families.end(),
                               [&](const VkQueueFamilyProperties& f) { return (f.queueFlags & needed) == needed; });
    if (family == families.end()) {
        throw InternalError("device '" + device_name() + "' has no queue family with both graphics and compute");
    }
    queue_family_ = static_cast<uint32_t>(family - families.begin());

    DeviceFeatureChain enable;
    const std::string lacking = request_device_features(physical_device_, enable);
    if (!lacking.empty()) throw InternalError("device '" + device_name() + "' lacks " + lacking);
    read_enabled_features(enable.features);

    const float priority = 1.0f;
    VkDeviceQueueCreateInfo queue_info{VK_STRUCTURE_TYPE_DEVICE_QUEUE_CREATE_INFO};
    queue_info.queueFamilyIndex = queue_family_;
    queue_info.queueCount = 1;
    queue_info.pQueuePriorities = &priority;

    // Push descriptors let each pass bind its resources at record time without pools
    // (lavapipe and the desktop drivers all expose the extension).
    std::vector<const char*> extensions{VK_KHR_PUSH_DESCRIPTOR_EXTENSION_NAME};
    if (swapchain) extensions.push_back(VK_KHR_SWAPCHAIN_EXTENSION_NAME);

    VkDeviceCreateInfo info{VK_STRUCTURE_TYPE_DEVICE_CREATE_INFO};
    info.pNext = &enable.features;
    info.queueCreateInfoCount = 1;
    info.pQueueCreateInfos = &queue_info;
    info.enabledExtensionCount = static_cast<uint32_t>(extensions.size());
    info.ppEnabledExtensionNames = extensions.data();
    VKW_CHECK(vkCreateDevice(physical_device_, &info, nullptr, &device_), "device '" + device_name() + "'");
    vkGetDeviceQueue(device_, queue_family_, 0, &queue_);
    load_device_functions();
    set_name(device_, VK_OBJECT_TYPE_DEVICE, "vkwater device");
    set_name(queue_, VK_OBJECT_TYPE_QUEUE, "vkwater queue");
    create_command_pool();
}

namespace {

// The first structure of type `type` in a pNext chain, or null.
template <class Struct>
const Struct* find_in_chain(const void* chain, VkStructureType type) {
    for (auto* node = static_cast<const VkBaseInStructure*>(chain); node; node = node->pNext) {
        if (node->sType == type) return reinterpret_cast<const Struct*>(node);
    }
    return nullptr;
}

}  // namespace

void Context::read_enabled_features(const VkPhysicalDeviceFeatures2& enabled) {
    const auto* enabled12 = find_in_chain<VkPhysicalDeviceVulkan12Features>(
        enabled.pNext, VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_2_FEATURES);
    const auto* enabled13 = find_in_chain<VkPhysicalDeviceVulkan13Features>(
        enabled.pNext, VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_3_FEATURES);
    if (!enabled13 || !enabled13->dynamicRendering || !enabled13->synchronization2) {
        throw InternalError("device '" + device_name() +
                            "' was created without dynamic rendering or synchronization2 "
                            "(VkPhysicalDeviceVulkan13Features in its feature chain)");
    }
    features_.depth_clamp = enabled.features.depthClamp;
    features_.shader_float64 = enabled.features.shaderFloat64;
    features_.shader_int64 = enabled.features.shaderInt64;
    features_.buffer_int64_atomics = enabled12 && enabled12->shaderBufferInt64Atomics;
    features_.shared_int64_atomics = enabled12 && enabled12->shaderSharedInt64Atomics;
    features_.wide_lines = enabled.features.wideLines;
    features_.fill_mode_non_solid = enabled.features.fillModeNonSolid;
    VkPhysicalDeviceVulkan13Properties properties13{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_3_PROPERTIES};
    VkPhysicalDeviceSubgroupProperties subgroup{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_SUBGROUP_PROPERTIES};
    subgroup.pNext = &properties13;
    VkPhysicalDeviceProperties2 properties{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_PROPERTIES_2};
    properties.pNext = &subgroup;
    vkGetPhysicalDeviceProperties2(physical_device_, &properties);
    // A subgroup wider than the 64-invocation work group that uses the shuffles would hold inactive
    // lanes, whose shuffled values are undefined.
    const uint32_t widest_subgroup = std::max(subgroup.subgroupSize, properties13.maxSubgroupSize);
    features_.compute_subgroup_shuffle_relative =
        (subgroup.supportedStages & VK_SHADER_STAGE_COMPUTE_BIT) &&
        (subgroup.supportedOperations & VK_SUBGROUP_FEATURE_SHUFFLE_RELATIVE_BIT) && widest_subgroup <= 64;
}

void Context::load_device_functions() {
    push_descriptor_set_ =
        reinterpret_cast<PFN_vkCmdPushDescriptorSetKHR>(vkGetDeviceProcAddr(device_, "vkCmdPushDescriptorSetKHR"));
    if (!push_descriptor_set_) {
        throw InternalError("device '" + device_name() + "' was created without " +
                            VK_KHR_PUSH_DESCRIPTOR_EXTENSION_NAME + ", which vkwater binds its resources with");
    }
}

void Context::create_command_pool() {
    VkCommandPoolCreateInfo pool_info{VK_STRUCTURE_TYPE_COMMAND_POOL_CREATE_INFO};
    pool_info.flags = VK_COMMAND_POOL_CREATE_TRANSIENT_BIT;
    pool_info.queueFamilyIndex = queue_family_;
    VKW_CHECK(vkCreateCommandPool(device_, &pool_info, allocator_, &command_pool_), "one-shot command pool");
    set_name(command_pool_, VK_OBJECT_TYPE_COMMAND_POOL, "one-shot command pool");
}

uint32_t Context::find_memory_type(uint32_t type_bits, VkMemoryPropertyFlags required) const {
    for (uint32_t i = 0; i < memory_properties_.memoryTypeCount; ++i) {
        if ((type_bits & (1u << i)) && (memory_properties_.memoryTypes[i].propertyFlags & required) == required) {
            return i;
        }
    }
    throw InternalError("device '" + device_name() + "' has no memory type with the needed properties");
}

void Context::set_name(VkObjectType type, uint64_t handle, const std::string& name) const {
    if (!set_object_name_ || handle == 0) return;
    VkDebugUtilsObjectNameInfoEXT info{VK_STRUCTURE_TYPE_DEBUG_UTILS_OBJECT_NAME_INFO_EXT};
    info.objectType = type;
    info.objectHandle = handle;
    info.pObjectName = name.c_str();
    set_object_name_(device_, &info);
}

void Context::forget_name(VkObjectType type, uint64_t handle) const {
    if (!set_object_name_ || handle == 0) return;
    VkDebugUtilsObjectNameInfoEXT info{VK_STRUCTURE_TYPE_DEBUG_UTILS_OBJECT_NAME_INFO_EXT};
    info.objectType = type;
    info.objectHandle = handle;
    info.pObjectName = nullptr;  // no name: the layer erases its entry
    set_object_name_(device_, &info);
}

void Context::begin_label(VkCommandBuffer cmd, const std::string& label) const {
    if (!begin_label_) return;
    VkDebugUtilsLabelEXT info{VK_STRUCTURE_TYPE_DEBUG_UTILS_LABEL_EXT};
    info.pLabelName = label.c_str();
    begin_label_(cmd, &info);
}

void Context::end_label(VkCommandBuffer cmd) const {
    if (end_label_) end_label_(cmd);
}

void Context::submit_and_wait(const std::function<void(VkCommandBuffer)>& record, const std::string& name) {
    VkCommandBufferAllocateInfo alloc{VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO};
    alloc.commandPool = command_pool_;
    alloc.level = VK_COMMAND_BUFFER_LEVEL_PRIMARY;
    alloc.commandBufferCount = 1;
    VkCommandBuffer cmd = VK_NULL_HANDLE;
    VKW_CHECK(vkAllocateCommandBuffers(device_, &alloc, &cmd), name);
    set_name(cmd, VK_OBJECT_TYPE_COMMAND_BUFFER, name);
    VkFence fence = VK_NULL_HANDLE;
    try {
        VkCommandBufferBeginInfo begin{VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO};
        begin.flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT;
        VKW_CHECK(vkBeginCommandBuffer(cmd, &begin), name);
        record(cmd);
        VKW_CHECK(vkEndCommandBuffer(cmd), name);
        VkFenceCreateInfo fence_info{VK_STRUCTURE_TYPE_FENCE_CREATE_INFO};
        VKW_CHECK(vkCreateFence(device_, &fence_info, allocator_, &fence), name);
        VkCommandBufferSubmitInfo cmd_info{VK_STRUCTURE_TYPE_COMMAND_BUFFER_SUBMIT_INFO};
        cmd_info.commandBuffer = cmd;
        VkSubmitInfo2 submit{VK_STRUCTURE_TYPE_SUBMIT_INFO_2};
        submit.commandBufferInfoCount = 1;
        submit.pCommandBufferInfos = &cmd_info;
        VKW_CHECK(vkQueueSubmit2(queue_, 1, &submit, fence), name);
        VKW_CHECK(vkWaitForFences(device_, 1, &fence, VK_TRUE, UINT64_MAX), name);
    } catch (...) {
        vkDeviceWaitIdle(device_);
        if (fence) vkDestroyFence(device_, fence, allocator_);
        vkFreeCommandBuffers(device_, command_pool_, 1, &cmd);
        throw;
    }
    vkDestroyFence(device_, fence, allocator_);
    vkFreeCommandBuffers(device_, command_pool_, 1, &cmd);
}

std::vector<std::string> list_device_names() {
    VkApplicationInfo app{VK_STRUCTURE_TYPE_APPLICATION_INFO};
    app.apiVersion = VK_API_VERSION_1_3;
    VkInstanceCreateInfo info{VK_STRUCTURE_TYPE_INSTANCE_CREATE_INFO};
    info.pApplicationInfo = &app;
    VkInstance instance = VK_NULL_HANDLE;
    if (vkCreateInstance(&info, nullptr, &instance) != VK_SUCCESS) return {};
    std::vector<std::string> names;
    for (VkPhysicalDevice device : enumerate_devices(instance)) {
        VkPhysicalDeviceProperties properties;
        vkGetPhysicalDeviceProperties(device, &properties);
        names.emplace_back(properties.deviceName);
    }
    vkDestroyInstance(instance, nullptr);
    return names;
}

}  // namespace vkw
