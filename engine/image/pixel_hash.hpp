// A fingerprint of an image's pixel data alone: two images with the same hash hold the same
// values bit for bit, whatever their files' attributes (the time, the device) say. A sequence's
// manifest records it per frame, and a re-run keeps a frame whose file still has it.
#pragma once

#include "engine/image/image.hpp"

#include <string>

namespace vkw {

// FNV-1a, 64 bits, over the width, the height, every RGBA value's bits, then each extra layer's
// name and values in the order of their names; printed as 16 hex digits. Attributes are left out.
std::string pixel_hash(const ImageRGBA32F& image);

}  // namespace vkw
