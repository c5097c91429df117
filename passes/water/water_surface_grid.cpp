// The grid kernels' shared C++ side: push-constant head, vertex buffer, banded dispatch
// (water_surface_grid.hpp).
#include "passes/water/water_surface_grid.hpp"

#include "engine/core/errors.hpp"
#include "engine/vk/context.hpp"

#include <algorithm>
#include <numeric>
#include <string>

namespace vkw::passes {

WaterGridPush water_grid_push(const WaterSurfaceInputs& inputs) {
    return {static_cast<float>(inputs.level), static_cast<float>(inputs.half_extent), inputs.grid_resolution, 0, 0};
}

fg::BufferHandle create_water_vertices(fg::PassBuilder& builder, uint32_t grid_resolution) {
    const fg::BufferHandle vertices = builder.create_buffer("water surface", {water_surface_bytes(grid_resolution)});
    return builder.write_storage("Vertices", vertices);
}

std::vector<WaterGridBand> water_grid_bands(VkDeviceSize max_range, VkDeviceSize alignment, uint32_t grid_resolution) {
    const uint32_t rows = grid_resolution + 1;
    const VkDeviceSize row_bytes = VkDeviceSize{rows} * kWaterVertexBytes;
    // Band offsets are multiples of `step` rows, the fewest rows whose bytes are aligned.
    const VkDeviceSize align = std::max<VkDeviceSize>(alignment, 1);
    const VkDeviceSize step = align / std::gcd(row_bytes, align);
    const VkDeviceSize fit = max_range / row_bytes / step * step;
    if (fit == 0) {
        throw InternalError("water surface: one row of " + std::to_string(rows) + " vertices (" +
                            std::to_string(row_bytes) + " bytes) exceeds the device's storage-buffer range of " +
                            std::to_string(max_range) + " bytes");
    }
    std::vector<WaterGridBand> bands;
    for (uint32_t first = 0; first < rows;) {
        const uint32_t count = static_cast<uint32_t>(std::min<VkDeviceSize>(fit, rows - first));
        bands.push_back({rows, first, count, first * row_bytes, count * row_bytes});
        first += count;
    }
    return bands;
}

std::vector<WaterGridBand> water_grid_bands(const fg::PassContext& context, uint32_t grid_resolution) {
    const VkPhysicalDeviceLimits& limits = context.context().properties().limits;
    return water_grid_bands(limits.maxStorageBufferRange, limits.minStorageBufferOffsetAlignment, grid_resolution);
}

void dispatch_water_band(fg::PassContext& context, const Pipeline& pipeline, fg::BufferHandle vertices,
                         const WaterGridBand& band, const void* push, uint32_t push_bytes) {
    context.bind(pipeline, {context.storage_buffer("Vertices", vertices, band.offset, band.bytes)});
    context.push_constants(pipeline, push, push_bytes);
    context.dispatch(pipeline, band.row_vertices, band.rows);
}

}  // namespace vkw::passes
