// HDR-FLIP (Andersson, Nilsson, Shirley, Akenine-Moller, "Visualizing Errors in Rendered High
// Dynamic Range Images", Eurographics 2021 short paper): LDR-FLIP over a range of exposures of
// both images, tone mapped alike, keeping each pixel's largest error.
#pragma once

#include <cstddef>
#include <span>
#include <vector>

#include "engine/image/image.hpp"
#include "tools/metrics/rgb_view.hpp"

namespace vkw::metrics {

// The observer: 67 pixels per degree of visual angle, the FLIP papers' default (a 0.7 m wide
// 3840-pixel display seen from 0.7 m: 0.7 * 3840 / 0.7 * pi / 180 = 67.02).
inline constexpr double kFlipPixelsPerDegree = 67.0;

// The exposures c_i = start + i (stop - start) / (count - 1), i = 0..count-1 (count = 1: just
// start). An image is exposed by multiplying it with 2^c.
struct FlipExposureRange {
    double start = 0.0;
    double stop = 0.0;
    int count = 1;

    double exposure(int i) const { return count > 1 ? start + i * (stop - start) / (count - 1) : start; }
};

// The paper's range, from the reference alone (so every test image compared against one
// reference is judged at the same exposures):
//   x_t = the input at which the tone mapper reaches t = 0.85 (positive root of
//         k0 x^2 + k1 x + k2 = t (k3 x^2 + k4 x + k5));
//   start = log2(x_t / Y_max): the brightest reference pixel is tone mapped to 0.85;
//   stop  = log2(x_t / Y_median): so is the median one;
//   count = max(2, ceil(stop - start)) (about one exposure per stop), 1 if start == stop.
// Y is the luminance of the reference's RGB (negative values as 0) over the whole image, the
// median of an even number of values the mean of the middle two. Two cases the paper leaves
// open: an all-black reference gives {0, 0, 1}; a median of 0 (more than half the pixels
// black) would put stop at infinity, so the median of the non-black pixels is used instead.
FlipExposureRange flip_exposure_range(const RgbView& reference);
FlipExposureRange flip_exposure_range(const ImageRGBA32F& reference);

// The tone mapper HDR-FLIP assumes by default: the ACES filmic fit of Narkowicz (2016),
// t(x) = (2.51 x^2 + 0.03 x) / (2.43 x^2 + 0.59 x + 0.14) clamped to [0, 1], applied to 0.6 x
// (Narkowicz's fit expects the input pre-scaled by 0.6; HDR-FLIP folds that in, giving
// k = (0.6^2 2.51, 0.6 0.03, 0, 0.6^2 2.43, 0.6 0.59, 0.14) over x). Negative x gives 0.
double hdr_flip_tone_map(double x);

// The input at which hdr_flip_tone_map reaches t, 0 < t < 1.
double hdr_flip_inverse_tone_map(double t);

// Per-pixel HDR-FLIP of test against reference, row-major, each in [0, 1]: for each exposure
// c of `range`, both images' RGB times 2^c (negative values as 0) go through the tone mapper
// and LDR-FLIP (kFlipPixelsPerDegree); each pixel keeps its largest error.
std::vector<float> hdr_flip_map(const RgbView& test, const RgbView& reference, const FlipExposureRange& range);

// LDR-FLIP of two images holding linear RGB in [0, 1] (values outside are clamped).
std::vector<float> ldr_flip_map(const RgbView& test, const RgbView& reference);

// Mean of hdr_flip_map over `pixels`. The filters see the whole image (a masked pixel's
// neighbours still matter to how it is perceived); only the average is restricted.
double flip_mean(const RgbView& test, const RgbView& reference, std::span<const std::size_t> pixels,
                 const FlipExposureRange& range);

}  // namespace vkw::metrics
