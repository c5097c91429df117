// The Vulkan instance, the chosen physical device, the logical device and its one
// queue. Picks a discrete, then integrated GPU, then a CPU device (lavapipe) unless
// the caller names one. Requires Vulkan 1.3 with dynamic rendering and
// synchronization2. With validation on, the Khronos layer runs with synchronization
// validation and every error or warning lands in validation_log() as a failure.
#pragma once

#include "engine/vk/validation_log.hpp"

#include <vulkan/vulkan.h>

#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace vkw {

struct ContextOptions {
    bool validation = false;
    std::string device_name;                       // substring of the device name; empty: best available
    std::vector<std::string> instance_extensions;  // e.g. what GLFW needs for a surface
    bool swapchain = false;                        // enable VK_KHR_swapchain on the device
    bool print_validation_messages = true;         // echo failures to stderr as they happen
};

// A host's Vulkan objects, lent to a context that records into the host's frames (the embedding
// library, include/vkwater/). The context destroys none of them; it makes its own command pool and
// submits its uploads on the lent queue, which the host must not use from another thread meanwhile.
struct BorrowedDevice {
    VkInstance instance = VK_NULL_HANDLE;
    VkPhysicalDevice physical_device = VK_NULL_HANDLE;
    VkDevice device = VK_NULL_HANDLE;
    VkQueue queue = VK_NULL_HANDLE;
    uint32_t queue_family = 0;  // must support graphics and compute
    // The feature chain the device was created with (VkDeviceCreateInfo::pNext): what vkwater may use
    // is read from it, never assumed. VkPhysicalDeviceVulkan12Features and ...13Features are read.
    const VkPhysicalDeviceFeatures2* enabled_features = nullptr;
    const VkAllocationCallbacks* allocator = nullptr;  // for every object the context makes; may be null
    bool debug_utils = false;  // VK_EXT_debug_utils is enabled on the instance: objects get names
};

// Optional device features vkwater uses when present; each pass checks what it needs.
struct DeviceFeatures {
    bool depth_clamp = false;
    bool shader_float64 = false;
    bool shader_int64 = false;
    bool buffer_int64_atomics = false;
    bool shared_int64_atomics = false;  // the caustic photons' workgroup tile (caustics_photons.hpp)
    // Subgroup shuffles by a relative lane in compute shaders, in subgroups of at most 64 lanes (a
    // property, nothing to enable): the adaptive caustic kernel's lanes share their photons' rays
    // (caustics_photons.cpp), in work groups of 64.
    bool compute_subgroup_shuffle_relative = false;
    bool wide_lines = false;
    bool fill_mode_non_solid = false;
};

class Context {
public:
    explicit Context(const ContextOptions& options);
    // Borrows the host's device; throws InternalError naming what it lacks (Vulkan 1.3, dynamic
    // rendering, synchronization2, VK_KHR_push_descriptor, a graphics and compute queue family).
    explicit Context(const BorrowedDevice& host);
    ~Context();
    Context(const Context&) = delete;
    Context& operator=(const Context&) = delete;

    VkInstance instance() const { return instance_; }
    VkPhysicalDevice physical_device() const { return physical_device_; }
    VkDevice device() const { return device_; }
    VkQueue queue() const { return queue_; }
    uint32_t queue_family() const { return queue_family_; }
    const VkPhysicalDeviceProperties& properties() const { return properties_; }
    const DeviceFeatures& features() const { return features_; }
    std::string device_name() const { return properties_.deviceName; }
    // CPU devices (lavapipe) leave raster and fragment work out of timestamps.
    bool is_cpu_device() const { return properties_.deviceType == VK_PHYSICAL_DEVICE_TYPE_CPU; }
    bool validation_enabled() const { return validation_; }
    // Whether the instance and device are the host's (BorrowedDevice): left alive at destruction.
    bool borrowed() const { return borrowed_; }
    // The host's allocation callbacks for every Vulkan object vkwater makes (null: the driver's).
    const VkAllocationCallbacks* allocator() const { return allocator_; }
    ValidationLog& validation_log() { return *validation_log_; }
    // Outlives the context, to read what its teardown reported.
    std::shared_ptr<ValidationLog> shared_validation_log() const { return validation_log_; }

    // vkCmdPushDescriptorSetKHR (VK_KHR_push_descriptor), loaded once.
    PFN_vkCmdPushDescriptorSetKHR push_descriptor_set() const { return push_descriptor_set_; }

    uint32_t find_memory_type(uint32_t type_bits, VkMemoryPropertyFlags required) const;

    // Debug-utils names and labels; no-ops when the extension is absent.
    void set_name(VkObjectType type, uint64_t handle, const std::string& name) const;
    template <class Handle>
    void set_name(Handle handle, VkObjectType type, const std::string& name) const {
        set_name(type, reinterpret_cast<uint64_t>(handle), name);
    }
    // Removes a name before its object is destroyed. The validation layer (1.3.239) keeps the
    // name of every handle it was given, destroyed or not, so a window resized a thousand times
    // grew by 36 MiB of names under validation; swapchain images, which are never destroyed one by
    // one, are the worst. Call it for objects made again and again.
    void forget_name(VkObjectType type, uint64_t handle) const;
    template <class Handle>
    void forget_name(Handle handle, VkObjectType type) const {
        forget_name(type, reinterpret_cast<uint64_t>(handle));
    }
    void begin_label(VkCommandBuffer cmd, const std::string& label) const;
    void end_label(VkCommandBuffer cmd) const;

    // How many of the costly objects this device has made so far: a frame that only moves a
    // clock or a slider must make none (the renderer's caching is tested by these counts).
    struct CreationCounts {
        uint64_t memory_allocations = 0;  // vkAllocateMemory
        uint64_t pipelines = 0;           // vkCreateGraphicsPipelines + vkCreateComputePipelines
    };
    const CreationCounts& creation_counts() const { return creation_counts_; }
    void count_memory_allocation() const { ++creation_counts_.memory_allocations; }
    void count_pipeline() const { ++creation_counts_.pipelines; }

    // Records with `record` into a fresh primary command buffer, submits, and waits.
    void submit_and_wait(const std::function<void(VkCommandBuffer)>& record, const std::string& name);

private:
    void create_instance(const ContextOptions& options);
    void pick_physical_device(const std::string& wanted_name);
    void create_device(bool swapchain);
    void read_enabled_features(const VkPhysicalDeviceFeatures2& enabled);
    void load_debug_utils();       // the names and labels of VK_EXT_debug_utils
    void load_device_functions();  // VK_KHR_push_descriptor's command
    void create_command_pool();
    void release();

    bool validation_ = false;
    bool borrowed_ = false;
    const VkAllocationCallbacks* allocator_ = nullptr;
    std::shared_ptr<ValidationLog> validation_log_;
    VkInstance instance_ = VK_NULL_HANDLE;
    VkDebugUtilsMessengerEXT messenger_ = VK_NULL_HANDLE;
    VkPhysicalDevice physical_device_ = VK_NULL_HANDLE;
    VkPhysicalDeviceProperties properties_{};
    VkPhysicalDeviceMemoryProperties memory_properties_{};
    DeviceFeatures features_;
    VkDevice device_ = VK_NULL_HANDLE;
    VkQueue queue_ = VK_NULL_HANDLE;
    uint32_t queue_family_ = 0;
    VkCommandPool command_pool_ = VK_NULL_HANDLE;
    PFN_vkCmdPushDescriptorSetKHR push_descriptor_set_ = nullptr;
    PFN_vkSetDebugUtilsObjectNameEXT set_object_name_ = nullptr;
    PFN_vkCmdBeginDebugUtilsLabelEXT begin_label_ = nullptr;
    PFN_vkCmdEndDebugUtilsLabelEXT end_label_ = nullptr;
    mutable CreationCounts creation_counts_;  // counting is not a change of the device
};

// The names of the physical devices Vulkan reports (for `--device` help and errors).
std::vector<std::string> list_device_names();

}  // namespace vkw
