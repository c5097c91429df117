// Native 32-bit float atomics for caustics_bench: vkw::Context does not enable
// VK_EXT_shader_atomic_float, so this makes a second VkDevice on the context's physical device
// (same instance, so the same validation layers) with shaderBufferFloat32AtomicAdd and
// shaderBufferInt64Atomics on, and times on it the scatter-only kernels with native float
// atomicAdd (shaders/caustics/bench/caustic_scatter_float_native.comp) and with int64 fixed point
// (caustic_scatter_fixed.comp), the same way the frame graph times passes on CPU devices: each
// dispatch submitted alone, fence-timed on the CPU clock (its target zeroed in an earlier,
// untimed submission). Raw Vulkan: the engine's helpers are tied to a vkw::Context's device.
#pragma once

#include "engine/vk/context.hpp"
#include "tools/benchmarks/caustic_scatter_passes.hpp"

#include <string>

namespace vkwbench {

// Empty when the device can run native float atomic adds on buffers; otherwise why not.
std::string native_float_atomics_missing(const vkw::Context& context);

struct NativeScatterTimes {
    double int64_ms = 0.0;    // median
    double float32_ms = 0.0;  // median
};

// The kernels with `push` (scatter_push); median of `runs` dispatches after one warm-up each.
NativeScatterTimes time_native_scatter(const vkw::Context& context, const ScatterPush& push, int runs);

}  // namespace vkwbench
