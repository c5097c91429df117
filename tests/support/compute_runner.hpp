// Runs one compute shader over a storage buffer and returns the buffer: how the
// shared GLSL includes (optics, phase functions, ...) are tested on the device,
// evaluating the shader code itself rather than a C++ copy of it.
#pragma once

#include "engine/vk/context.hpp"
#include "engine/vk/pipeline.hpp"
#include "engine/vk/resources.hpp"

#include <cstring>
#include <string>
#include <vector>

namespace vkw::test {

// The shader reads push constants (`push_bytes` of `push`) and writes binding 0, a
// std430 storage buffer of `output_floats` floats; `groups` work groups in x.
inline std::vector<float> run_compute(Context& context, const std::string& shader, const void* push,
                                      uint32_t push_bytes, size_t output_floats, uint32_t groups) {
    Buffer output(context, {output_floats * sizeof(float), VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, /*host_visible=*/true},
                  shader + " output");
    std::memset(output.mapped(), 0xff, output_floats * sizeof(float));  // NaN: unwritten values show
    ComputePipelineDesc desc;
    desc.shader = shader;
    desc.layout.bindings = {{0, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, 1, VK_SHADER_STAGE_COMPUTE_BIT}};
    desc.layout.push_constant_bytes = push_bytes;
    Pipeline pipeline(context, desc, shader);
    context.submit_and_wait(
        [&](VkCommandBuffer cmd) {
            vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, pipeline.handle());
            VkDescriptorBufferInfo info{output.handle(), 0, VK_WHOLE_SIZE};
            VkWriteDescriptorSet write{VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET};
            write.descriptorCount = 1;
            write.descriptorType = VK_DESCRIPTOR_TYPE_STORAGE_BUFFER;
            write.pBufferInfo = &info;
            context.push_descriptor_set()(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, pipeline.layout(), 0, 1, &write);
            vkCmdPushConstants(cmd, pipeline.layout(), VK_SHADER_STAGE_ALL, 0, push_bytes, push);
            vkCmdDispatch(cmd, groups, 1, 1);
            // Make the shader's writes visible to the host before the fence signals.
            VkMemoryBarrier2 to_host{VK_STRUCTURE_TYPE_MEMORY_BARRIER_2};
            to_host.srcStageMask = VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT;
            to_host.srcAccessMask = VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT;
            to_host.dstStageMask = VK_PIPELINE_STAGE_2_HOST_BIT;
            to_host.dstAccessMask = VK_ACCESS_2_HOST_READ_BIT;
            VkDependencyInfo dependency{VK_STRUCTURE_TYPE_DEPENDENCY_INFO};
            dependency.memoryBarrierCount = 1;
            dependency.pMemoryBarriers = &to_host;
            vkCmdPipelineBarrier2(cmd, &dependency);
        },
        shader);
    std::vector<float> values(output_floats);
    std::memcpy(values.data(), output.mapped(), output_floats * sizeof(float));
    return values;
}

}  // namespace vkw::test
