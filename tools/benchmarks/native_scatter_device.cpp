// The scatter-only kernels on a device with native float atomics (native_scatter_device.hpp).
#include "tools/benchmarks/native_scatter_device.hpp"

#include "engine/core/errors.hpp"
#include "engine/vk/check.hpp"
#include "engine/vk/shader_module.hpp"

#include <algorithm>
#include <chrono>
#include <cstring>
#include <fstream>
#include <vector>

namespace vkwbench {
namespace {

using namespace vkw;

std::vector<uint32_t> read_spirv(const std::string& name) {
    const std::filesystem::path path = shader_directory() / (name + ".spv");
    std::ifstream file(path, std::ios::binary | std::ios::ate);
    if (!file) throw InternalError("native scatter: cannot read " + path.string());
    std::vector<uint32_t> words(size_t(file.tellg()) / 4);
    file.seekg(0);
    file.read(reinterpret_cast<char*>(words.data()), std::streamsize(words.size() * 4));
    return words;
}

double median(std::vector<double> values) {
    std::sort(values.begin(), values.end());
    return values[values.size() / 2];
}

// The second device and what both kernels share; destroyed in reverse order.
class NativeScatterDevice {
public:
    explicit NativeScatterDevice(const Context& context) : context_(context) {
        VkPhysicalDeviceShaderAtomicFloatFeaturesEXT atomic_float{
            VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_SHADER_ATOMIC_FLOAT_FEATURES_EXT};
        atomic_float.shaderBufferFloat32AtomicAdd = VK_TRUE;
        VkPhysicalDeviceVulkan13Features vulkan13{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_3_FEATURES, &atomic_float};
        vulkan13.synchronization2 = VK_TRUE;  // vkCmdPipelineBarrier2, vkQueueSubmit2
        vulkan13.maintenance4 = VK_TRUE;      // glslang's vulkan1.3 SPIR-V declares LocalSizeId
        VkPhysicalDeviceVulkan12Features vulkan12{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_2_FEATURES, &vulkan13};
        vulkan12.shaderBufferInt64Atomics = VK_TRUE;
        VkPhysicalDeviceFeatures2 features{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_FEATURES_2, &vulkan12};
        features.features.shaderInt64 = VK_TRUE;
        const float priority = 1.0f;
        VkDeviceQueueCreateInfo queue{VK_STRUCTURE_TYPE_DEVICE_QUEUE_CREATE_INFO};
        queue.queueFamilyIndex = context.queue_family();
        queue.queueCount = 1;
        queue.pQueuePriorities = &priority;
        const char* extension = VK_EXT_SHADER_ATOMIC_FLOAT_EXTENSION_NAME;
        VkDeviceCreateInfo info{VK_STRUCTURE_TYPE_DEVICE_CREATE_INFO, &features};
        info.queueCreateInfoCount = 1;
        info.pQueueCreateInfos = &queue;
        info.enabledExtensionCount = 1;
        info.ppEnabledExtensionNames = &extension;
        VKW_CHECK(vkCreateDevice(context.physical_device(), &info, nullptr, &device_), "native scatter device");
        vkGetDeviceQueue(device_, context.queue_family(), 0, &queue_);

        VkCommandPoolCreateInfo pool{VK_STRUCTURE_TYPE_COMMAND_POOL_CREATE_INFO};
        pool.flags = VK_COMMAND_POOL_CREATE_RESET_COMMAND_BUFFER_BIT;
        pool.queueFamilyIndex = context.queue_family();
        VKW_CHECK(vkCreateCommandPool(device_, &pool, nullptr, &command_pool_), "native scatter command pool");
        VkCommandBufferAllocateInfo allocate{VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO};
        allocate.commandPool = command_pool_;
        allocate.level = VK_COMMAND_BUFFER_LEVEL_PRIMARY;
        allocate.commandBufferCount = 1;
        VKW_CHECK(vkAllocateCommandBuffers(device_, &allocate, &cmd_), "native scatter command buffer");
        VkFenceCreateInfo fence{VK_STRUCTURE_TYPE_FENCE_CREATE_INFO};
        VKW_CHECK(vkCreateFence(device_, &fence, nullptr, &fence_), "native scatter fence");

        VkDescriptorSetLayoutBinding binding{0, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, 1, VK_SHADER_STAGE_COMPUTE_BIT,
                                             nullptr};
        VkDescriptorSetLayoutCreateInfo set_layout{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_LAYOUT_CREATE_INFO};
        set_layout.bindingCount = 1;
        set_layout.pBindings = &binding;
        VKW_CHECK(vkCreateDescriptorSetLayout(device_, &set_layout, nullptr, &set_layout_),
                  "native scatter set layout");
        const VkPushConstantRange push{VK_SHADER_STAGE_COMPUTE_BIT, 0, sizeof(ScatterPush)};
        VkPipelineLayoutCreateInfo layout{VK_STRUCTURE_TYPE_PIPELINE_LAYOUT_CREATE_INFO};
        layout.setLayoutCount = 1;
        layout.pSetLayouts = &set_layout_;
        layout.pushConstantRangeCount = 1;
        layout.pPushConstantRanges = &push;
        VKW_CHECK(vkCreatePipelineLayout(device_, &layout, nullptr, &pipeline_layout_), "native scatter layout");
        const VkDescriptorPoolSize size{VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, 1};
        VkDescriptorPoolCreateInfo descriptor_pool{VK_STRUCTURE_TYPE_DESCRIPTOR_POOL_CREATE_INFO};
        descriptor_pool.maxSets = 1;
        descriptor_pool.poolSizeCount = 1;
        descriptor_pool.pPoolSizes = &size;
        VKW_CHECK(vkCreateDescriptorPool(device_, &descriptor_pool, nullptr, &descriptor_pool_),
                  "native scatter descriptor pool");
        VkDescriptorSetAllocateInfo set{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_ALLOCATE_INFO};
        set.descriptorPool = descriptor_pool_;
        set.descriptorSetCount = 1;
        set.pSetLayouts = &set_layout_;
        VKW_CHECK(vkAllocateDescriptorSets(device_, &set, &set_), "native scatter descriptor set");
    }

    ~NativeScatterDevice() {
        if (!device_) return;
        vkDeviceWaitIdle(device_);
        if (buffer_) vkDestroyBuffer(device_, buffer_, nullptr);
        if (memory_) vkFreeMemory(device_, memory_, nullptr);
        vkDestroyDescriptorPool(device_, descriptor_pool_, nullptr);
        vkDestroyPipelineLayout(device_, pipeline_layout_, nullptr);
        vkDestroyDescriptorSetLayout(device_, set_layout_, nullptr);
        vkDestroyFence(device_, fence_, nullptr);
        vkDestroyCommandPool(device_, command_pool_, nullptr);
        vkDestroyDevice(device_, nullptr);
    }
    NativeScatterDevice(const NativeScatterDevice&) = delete;
    NativeScatterDevice& operator=(const NativeScatterDevice&) = delete;

    // One target for both kernels, sized for the larger (int64) one.
    void create_target(VkDeviceSize bytes) {
        VkBufferCreateInfo info{VK_STRUCTURE_TYPE_BUFFER_CREATE_INFO};
        info.size = bytes;
        info.usage = VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_TRANSFER_DST_BIT;
        VKW_CHECK(vkCreateBuffer(device_, &info, nullptr, &buffer_), "native scatter target");
        VkMemoryRequirements requirements;
        vkGetBufferMemoryRequirements(device_, buffer_, &requirements);
        VkMemoryAllocateInfo allocate{VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO};
        allocate.allocationSize = requirements.size;
        allocate.memoryTypeIndex =
            context_.find_memory_type(requirements.memoryTypeBits, VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT);
        VKW_CHECK(vkAllocateMemory(device_, &allocate, nullptr, &memory_), "native scatter target memory");
        VKW_CHECK(vkBindBufferMemory(device_, buffer_, memory_, 0), "native scatter target memory");
        const VkDescriptorBufferInfo target{buffer_, 0, bytes};
        VkWriteDescriptorSet write{VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET};
        write.dstSet = set_;
        write.descriptorCount = 1;
        write.descriptorType = VK_DESCRIPTOR_TYPE_STORAGE_BUFFER;
        write.pBufferInfo = &target;
        vkUpdateDescriptorSets(device_, 1, &write, 0, nullptr);
    }

    // Median ms of `runs` dispatches of `shader` (after one warm-up), each on a zeroed target.
    double time_kernel(const std::string& shader, const ScatterPush& push, int runs) {
        const std::vector<uint32_t> code = read_spirv(shader);
        VkShaderModuleCreateInfo module_info{VK_STRUCTURE_TYPE_SHADER_MODULE_CREATE_INFO};
        module_info.codeSize = code.size() * 4;
        module_info.pCode = code.data();
        VkShaderModule module = VK_NULL_HANDLE;
        VKW_CHECK(vkCreateShaderModule(device_, &module_info, nullptr, &module), "native scatter shader");
        VkComputePipelineCreateInfo pipeline_info{VK_STRUCTURE_TYPE_COMPUTE_PIPELINE_CREATE_INFO};
        pipeline_info.stage = {VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO,
                               nullptr,
                               0,
                               VK_SHADER_STAGE_COMPUTE_BIT,
                               module,
                               "main",
                               nullptr};
        pipeline_info.layout = pipeline_layout_;
        VkPipeline pipeline = VK_NULL_HANDLE;
        VKW_CHECK(vkCreateComputePipelines(device_, VK_NULL_HANDLE, 1, &pipeline_info, nullptr, &pipeline),
                  "native scatter pipeline");
        vkDestroyShaderModule(device_, module, nullptr);

        std::vector<double> times;
        for (int run = 0; run <= runs; ++run) {
            submit_and_wait([&](VkCommandBuffer cmd) {
                // The previous run's atomics before the fill overwrites them.
                target_barrier(cmd, VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT, VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT,
                               VK_PIPELINE_STAGE_2_ALL_TRANSFER_BIT, VK_ACCESS_2_TRANSFER_WRITE_BIT);
                vkCmdFillBuffer(cmd, buffer_, 0, VK_WHOLE_SIZE, 0);
            });
            const double ms = submit_and_wait([&](VkCommandBuffer cmd) {
                // The fill (previous submission) before the kernel's reads and writes.
                target_barrier(cmd, VK_PIPELINE_STAGE_2_ALL_TRANSFER_BIT, VK_ACCESS_2_TRANSFER_WRITE_BIT,
                               VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT,
                               VK_ACCESS_2_SHADER_STORAGE_READ_BIT | VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT);
                vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, pipeline);
                vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, pipeline_layout_, 0, 1, &set_, 0, nullptr);
                vkCmdPushConstants(cmd, pipeline_layout_, VK_SHADER_STAGE_COMPUTE_BIT, 0, sizeof push, &push);
                const uint32_t groups = (push.resolution + kScatterGroupSide - 1) / kScatterGroupSide;
                vkCmdDispatch(cmd, groups, groups, 1);
            });
            if (run > 0) times.push_back(ms);  // run 0 warms llvmpipe's shader variant up
        }
        vkDestroyPipeline(device_, pipeline, nullptr);
        return median(times);
    }

private:
    void target_barrier(VkCommandBuffer cmd, VkPipelineStageFlags2 src_stage, VkAccessFlags2 src_access,
                        VkPipelineStageFlags2 dst_stage, VkAccessFlags2 dst_access) const {
        VkBufferMemoryBarrier2 barrier{VK_STRUCTURE_TYPE_BUFFER_MEMORY_BARRIER_2};
        barrier.srcStageMask = src_stage;
        barrier.srcAccessMask = src_access;
        barrier.dstStageMask = dst_stage;
        barrier.dstAccessMask = dst_access;
        barrier.srcQueueFamilyIndex = barrier.dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
        barrier.buffer = buffer_;
        barrier.size = VK_WHOLE_SIZE;
        VkDependencyInfo dependency{VK_STRUCTURE_TYPE_DEPENDENCY_INFO};
        dependency.bufferMemoryBarrierCount = 1;
        dependency.pBufferMemoryBarriers = &barrier;
        vkCmdPipelineBarrier2(cmd, &dependency);
    }

    // Records, submits and waits; returns the CPU time from submission to the fence, ms.
    template <class Record>
    double submit_and_wait(Record record) {
        VKW_CHECK(vkResetCommandBuffer(cmd_, 0), "native scatter command buffer");
        VkCommandBufferBeginInfo begin{VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO};
        begin.flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT;
        VKW_CHECK(vkBeginCommandBuffer(cmd_, &begin), "native scatter command buffer");
        record(cmd_);
        VKW_CHECK(vkEndCommandBuffer(cmd_), "native scatter command buffer");
        VkCommandBufferSubmitInfo command{VK_STRUCTURE_TYPE_COMMAND_BUFFER_SUBMIT_INFO};
        command.commandBuffer = cmd_;
        VkSubmitInfo2 submit{VK_STRUCTURE_TYPE_SUBMIT_INFO_2};
        submit.commandBufferInfoCount = 1;
        submit.pCommandBufferInfos = &command;
        const auto start = std::chrono::steady_clock::now();
        VKW_CHECK(vkQueueSubmit2(queue_, 1, &submit, fence_), "native scatter submission");
        VKW_CHECK(vkWaitForFences(device_, 1, &fence_, VK_TRUE, UINT64_MAX), "native scatter fence");
        const double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
        VKW_CHECK(vkResetFences(device_, 1, &fence_), "native scatter fence");
        return ms;
    }

    const Context& context_;
    VkDevice device_ = VK_NULL_HANDLE;
    VkQueue queue_ = VK_NULL_HANDLE;
    VkCommandPool command_pool_ = VK_NULL_HANDLE;
    VkCommandBuffer cmd_ = VK_NULL_HANDLE;
    VkFence fence_ = VK_NULL_HANDLE;
    VkDescriptorSetLayout set_layout_ = VK_NULL_HANDLE;
    VkPipelineLayout pipeline_layout_ = VK_NULL_HANDLE;
    VkDescriptorPool descriptor_pool_ = VK_NULL_HANDLE;
    VkDescriptorSet set_ = VK_NULL_HANDLE;
    VkBuffer buffer_ = VK_NULL_HANDLE;
    VkDeviceMemory memory_ = VK_NULL_HANDLE;
};

}  // namespace

std::string native_float_atomics_missing(const Context& context) {
    uint32_t count = 0;
    vkEnumerateDeviceExtensionProperties(context.physical_device(), nullptr, &count, nullptr);
    std::vector<VkExtensionProperties> extensions(count);
    vkEnumerateDeviceExtensionProperties(context.physical_device(), nullptr, &count, extensions.data());
    const bool listed = std::any_of(extensions.begin(), extensions.end(), [](const VkExtensionProperties& e) {
        return std::strcmp(e.extensionName, VK_EXT_SHADER_ATOMIC_FLOAT_EXTENSION_NAME) == 0;
    });
    if (!listed) return "the device lacks VK_EXT_shader_atomic_float";
    VkPhysicalDeviceShaderAtomicFloatFeaturesEXT atomic_float{
        VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_SHADER_ATOMIC_FLOAT_FEATURES_EXT};
    VkPhysicalDeviceFeatures2 features{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_FEATURES_2, &atomic_float};
    vkGetPhysicalDeviceFeatures2(context.physical_device(), &features);
    if (!atomic_float.shaderBufferFloat32AtomicAdd) return "the device reports shaderBufferFloat32AtomicAdd = false";
    if (!context.features().buffer_int64_atomics) return "the device lacks shaderBufferInt64Atomics";
    return {};
}

NativeScatterTimes time_native_scatter(const Context& context, const ScatterPush& push, int runs) {
    NativeScatterDevice device(context);
    const VkDeviceSize bytes = VkDeviceSize{push.width} * push.height * 3 * sizeof(uint64_t);
    if (bytes > context.properties().limits.maxStorageBufferRange) {
        throw InternalError("native scatter: a map of " + std::to_string(push.width) + " x " +
                            std::to_string(push.height) + " texels exceeds one storage-buffer binding");
    }
    device.create_target(bytes);
    NativeScatterTimes times;
    times.int64_ms = device.time_kernel("caustics/bench/caustic_scatter_fixed.comp", push, runs);
    times.float32_ms = device.time_kernel("caustics/bench/caustic_scatter_float_native.comp", push, runs);
    return times;
}

}  // namespace vkwbench
