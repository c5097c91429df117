// Requests beyond what the device can hold are user errors. The tests size those requests from the
// limits of the device vkwater picks, so they hold on any device.
#include "engine/vk/context.hpp"
#include "passes/caustics/caustics_camera_receivers.hpp"
#include "passes/caustics/caustics_camera_splats.hpp"
#include "passes/water/water_surface.hpp"
#include "tests/cli/cli_support.hpp"

#include <algorithm>

namespace vkw::cli_test {
namespace {

// The limits of the device vkwater picks by default (the same rule: a discrete GPU, then an
// integrated one, then lavapipe), read once. The tests of requests beyond the device size them
// from these, so they hold on any device, and skip where nothing the formats accept goes beyond.
struct DeviceLimits {
    std::string name;
    VkDeviceSize storage_range = 0;  // maxStorageBufferRange
    VkDeviceSize largest_heap = 0;
    uint32_t max_image_side = 0;  // maxImageDimension2D
    bool cpu_device = false;      // lavapipe: CI's device, whose limits the tests must exceed
};

const DeviceLimits& default_device_limits() {
    static const DeviceLimits limits = [] {
        const Context context(ContextOptions{});
        DeviceLimits read;
        read.name = context.device_name();
        read.storage_range = context.properties().limits.maxStorageBufferRange;
        read.max_image_side = context.properties().limits.maxImageDimension2D;
        read.cpu_device = context.is_cpu_device();
        VkPhysicalDeviceMemoryProperties memory;
        vkGetPhysicalDeviceMemoryProperties(context.physical_device(), &memory);
        for (uint32_t i = 0; i < memory.memoryHeapCount; ++i)
            read.largest_heap = std::max(read.largest_heap, memory.memoryHeaps[i].size);
        return read;
    }();
    return limits;
}

TEST(cli, CameraSpaceSplatsBeyondOneStorageBindingAreAUserError) {
    // The smallest 4:3 output (in steps of 256x192 pixels) whose camera-space flux buffer is
    // larger than one storage binding of the device.
    const DeviceLimits& device = default_device_limits();
    uint32_t width = 0, height = 0;
    for (uint32_t step = 1; 256 * step <= device.max_image_side; ++step) {
        const uint32_t w = 256 * step, h = 192 * step;
        if (passes::camera_caustic_flux_bytes(passes::camera_caustic_extent(w, h)) > device.storage_range) {
            width = w, height = h;
            break;
        }
    }
    if (width == 0) {
        // Only a GPU's limits may be out of reach; on CI's lavapipe this would hide the test.
        ASSERT_FALSE(device.cpu_device) << "lavapipe's storage binding holds every output";
        GTEST_SKIP() << "every output up to " << device.max_image_side << " pixels a side fits one storage binding of '"
                     << device.name << "' (" << (device.storage_range >> 20) << " MiB)";
    }
    const CommandRun run =
        run_vkwater("render " + kPool + " --out " + scratch("big.exr").string() + " --width " + std::to_string(width) +
                    " --height " + std::to_string(height) + " --set effects.caustics.splat=camera-space");
    EXPECT_EQ(run.exit_code, 1) << run.output;
    EXPECT_NE(run.output.find("pool.json: effects.caustics.splat"), std::string::npos) << run.output;
    EXPECT_NE(run.output.find("or splat light-space"), std::string::npos) << run.output;
}

TEST(cli, WaterGridBeyondTheDeviceIsAUserError) {
    // The renderer's rule (passes/frame/renderer.cpp): the surface's vertices in one storage
    // binding and within a quarter of the largest heap. The smallest power-of-two grid beyond
    // it, if the scene format (at most 4096 cells a side) accepts one.
    const DeviceLimits& device = default_device_limits();
    const VkDeviceSize limit = std::min(device.largest_heap / 4, device.storage_range);
    uint32_t grid = 2;
    while (grid <= 4096 && passes::water_surface_bytes(grid) <= limit) grid *= 2;
    if (grid > 4096) {
        ASSERT_FALSE(device.cpu_device) << "lavapipe holds every water grid";  // as above
        GTEST_SKIP() << "every water grid the scene format accepts (up to 4096 cells a side) fits '" << device.name
                     << "' (" << (limit >> 20) << " MiB for the surface)";
    }
    const std::string cells = std::to_string(grid);
    expect_clean_failure(run_vkwater("render " + kPool + " --out " + scratch("x.exr").string() +
                                     " --set water.grid_resolution=" + cells),
                         1, "water.grid_resolution: " + cells + " needs");
}

}  // namespace
}  // namespace vkw::cli_test
