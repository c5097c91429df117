// Box downsampling for the errors at reduced resolution: each factor x factor block of pixels
// becomes one pixel holding the block's mean. An error that only moves light inside a block
// (a caustic line drawn a texel off) vanishes; one that changes a block's energy stays. So the
// error at 4x separates energy errors from sub-texel misplacement.
#pragma once

#include "engine/image/image.hpp"

namespace vkw::metrics {

// The factor `vkwater bench` reports its reduced-resolution errors at.
inline constexpr int kBenchDownsampleFactor = 4;

// The mean of every factor x factor block, for R, G, B, A and every extra layer, summed in
// double and rounded once to float. The result is floor(width / factor) x floor(height /
// factor): a partial block at the right or bottom edge is left out (a mean over fewer pixels
// would weigh them differently). factor 1 returns a copy.
// Throws UserError unless 1 <= factor <= min(width, height), naming the accepted range.
ImageRGBA32F box_downsample(const ImageRGBA32F& image, int factor);

// A mask (R > 0.5 selects a pixel, as counted_pixels reads it) reduced alike: a block is
// selected (R = G = B = A = 1) only when every one of its pixels is, else 0, so a block
// that mixes counted and left-out pixels never counts.
ImageRGBA32F box_downsample_mask(const ImageRGBA32F& mask, int factor);

}  // namespace vkw::metrics
