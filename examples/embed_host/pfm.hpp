// Portable float maps: the simplest lossless file for linear float images, which vkwater's own
// tools (vkwater compare) and most image viewers read.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace embed_host {

// Writes an RGB PFM ("PF", scale -1: little-endian floats). `rgb` holds width * height * 3 floats,
// top row first as Vulkan images are; PFM stores the bottom row first, so the rows are flipped.
// Returns false (errno tells why) when the file cannot be written.
bool write_pfm(const std::string& path, uint32_t width, uint32_t height, const std::vector<float>& rgb);

}  // namespace embed_host
