// How the caustic passes keep every storage-buffer binding within maxStorageBufferRange (128 MiB
// on lavapipe) and every dispatch within 65535 work groups per dimension: buffers of rows are
// bound band by band, each band's offset aligned to minStorageBufferOffsetAlignment.
//
// The flux buffer: a header of kCausticFluxHeaderBytes (the uint64 flux per channel that fell off
// the map, then padding to the largest offset alignment Vulkan allows), then the held texels
// (CausticMapFrame::held: the whole W x H map, or the rectangle the frame reads) of three uint64
// (R, G, B), row after row at the rectangle's width. It is allocated for the whole map.
#pragma once

#include <vulkan/vulkan.h>

#include <cstdint>
#include <vector>

namespace vkw::passes {

inline constexpr VkDeviceSize kCausticFluxHeaderBytes = 256;
inline constexpr VkDeviceSize kCausticTexelBytes = 3 * sizeof(uint64_t);

VkDeviceSize caustic_flux_bytes(uint32_t width, uint32_t height);

struct RowBand {
    uint32_t first = 0, rows = 0;        // the band's rows
    VkDeviceSize offset = 0, bytes = 0;  // its binding: the rows plus `extra_rows` after them
};

// Splits `total` rows of `row_bytes` each, stored from byte `base` on, into bands of at most
// `max_rows` rows whose binding (the band plus `extra_rows` following rows, which must exist: a
// cell row reads the vertex row after it) spans at most `max_range` bytes and starts at an offset
// that is a multiple of `alignment`. Throws vkw::InternalError when not even one row fits.
std::vector<RowBand> row_bands(uint32_t total, VkDeviceSize row_bytes, VkDeviceSize base, uint32_t extra_rows,
                               VkDeviceSize max_range, VkDeviceSize alignment, uint32_t max_rows);

}  // namespace vkw::passes
