// The numbers `vkwater compare` prints for a test image against a reference (B, the CPU ground
// truth): relMSE (primary), HDR-FLIP mean, signed mean bias and the CIE L*u*v* mean distance.
// All compare R, G, B only (alpha is ignored) over the counted pixels (all, or a mask's).
#pragma once

#include <cstddef>
#include <span>
#include <string>

#include "engine/image/image.hpp"
#include "tools/metrics/flip/hdr_flip.hpp"
#include "tools/metrics/rgb_view.hpp"

namespace vkw::metrics {

struct Metrics {
    double rel_mse = 0.0;    // rel_mse()
    double flip_mean = 0.0;  // flip_mean()
    double bias = 0.0;       // mean_bias()
    double luv_mean = 0.0;   // luv_mean_distance()
};

// The epsilon of relMSE's denominator, in units of the reference's mean (which is 1 after the
// scaling): it keeps near-black reference values from dominating.
inline constexpr double kRelMseEpsilon = 0.01;

// relMSE, exactly:
//   P  = the counted pixels, n = 3 |P| values (R, G, B of each);
//   s  = mean of the reference's n values; both images are divided by s (the reference's mean
//        becomes 1, so the number does not depend on the overall brightness);
//   e_i = (a_i/s - b_i/s)^2 / ((b_i/s)^2 + kRelMseEpsilon) for each of the n values;
//   k  = floor(0.001 n), computed as the integer n / 1000: the worst 0.1% of the values;
//   relMSE = (sum of the n - k smallest e_i) / (n - k). Ties among the largest are
//   interchangeable (equal values), so which of them is dropped does not matter.
// Dropping the worst 0.1% keeps a few fireflies of a Monte Carlo reference (or of the test)
// from deciding the number. Throws UserError if s <= 0 or the inputs fail require_comparable.
double rel_mse(const RgbView& test, const RgbView& reference, std::span<const std::size_t> pixels);

// The energy check: mean(a) / mean(b) - 1 over the same n values, signed (negative: the test
// is darker). Throws UserError if mean(b) <= 0.
double mean_bias(const RgbView& test, const RgbView& reference, std::span<const std::size_t> pixels);

// Mean CIE 1976 L*u*v* distance (Tipprasert 2006, eq. 2-9: the mean over the compared pixels of
// sqrt(dL*^2 + du*^2 + dv*^2)), for comparison with older work. Both images are multiplied by
// one exposure, 0.18 / (mean luminance of the reference over P), so the reference's mean
// luminance becomes middle grey 0.18; each exposed value is clamped to [0, 1] (what an sRGB
// display shows) and converted linear sRGB -> XYZ -> L*u*v* with the D65 white (Y = 1).
// Throws UserError if the reference's mean luminance is <= 0.
double luv_mean_distance(const RgbView& test, const RgbView& reference, std::span<const std::size_t> pixels);

// All four metrics of the main RGB. `mask`: pixels with mask R > 0.5 count (nullptr: all).
// `range`: the HDR-FLIP exposures; nullptr computes flip_exposure_range(reference), pass one
// computed once to compare several test images against the same reference alike.
// Throws UserError for a size mismatch, an empty mask, non-finite values or a black reference.
Metrics compare_images(const ImageRGBA32F& test, const ImageRGBA32F& reference, const ImageRGBA32F* mask = nullptr,
                       const FlipExposureRange* range = nullptr);

// The same for the extra layer `layer` (e.g. "caustic") of both images; a nullptr `range` is
// computed from the reference's layer. Throws UserError if either image lacks the layer.
Metrics compare_layer(const ImageRGBA32F& test, const ImageRGBA32F& reference, const std::string& layer,
                      const ImageRGBA32F* mask = nullptr, const FlipExposureRange* range = nullptr);

}  // namespace vkw::metrics
