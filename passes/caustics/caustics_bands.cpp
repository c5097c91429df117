// Row bands for the caustic passes' bindings and dispatches (caustics_bands.hpp).
#include "passes/caustics/caustics_bands.hpp"

#include "engine/core/errors.hpp"

#include <algorithm>
#include <numeric>
#include <string>

namespace vkw::passes {

VkDeviceSize caustic_flux_bytes(uint32_t width, uint32_t height) {
    return kCausticFluxHeaderBytes + VkDeviceSize{width} * height * kCausticTexelBytes;
}

std::vector<RowBand> row_bands(uint32_t total, VkDeviceSize row_bytes, VkDeviceSize base, uint32_t extra_rows,
                               VkDeviceSize max_range, VkDeviceSize alignment, uint32_t max_rows) {
    const VkDeviceSize align = std::max<VkDeviceSize>(alignment, 1);
    if (base % align != 0) throw InternalError("row_bands: base offset not aligned");
    // Band starts are multiples of `step` rows, the fewest rows whose bytes are aligned.
    const VkDeviceSize step = align / std::gcd(row_bytes, align);
    const VkDeviceSize by_range = max_range / row_bytes;
    VkDeviceSize fit = by_range > extra_rows ? by_range - extra_rows : 0;
    fit = std::min<VkDeviceSize>(fit, max_rows);
    if (fit >= step) fit = fit / step * step;
    if (fit == 0 || (fit < step && fit < total)) {
        throw InternalError("row_bands: rows of " + std::to_string(row_bytes) + " bytes do not fit a binding of " +
                            std::to_string(max_range) + " bytes with offset alignment " + std::to_string(align));
    }
    std::vector<RowBand> bands;
    for (uint32_t first = 0; first < total;) {
        const uint32_t rows = static_cast<uint32_t>(std::min<VkDeviceSize>(fit, total - first));
        bands.push_back({first, rows, base + first * row_bytes, (rows + extra_rows) * row_bytes});
        first += rows;
    }
    return bands;
}

}  // namespace vkw::passes
