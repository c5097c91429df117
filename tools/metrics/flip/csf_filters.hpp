// FLIP's colour pipeline, step 1: the contrast sensitivity functions (CSFs) of the three
// opponent channels, as spatial filters (FLIP paper, Andersson et al. 2020, "spatial filtering"
// of the colour pipeline).
#pragma once

#include <vector>

#include "tools/metrics/flip/plane.hpp"

namespace vkw::metrics::flip {

// The opponent channels of YCxCz, in plane order.
enum class OpponentChannel { Achromatic = 0, RedGreen = 1, BlueYellow = 2 };

// A channel's CSF filter as a weighted sum of separable Gaussians:
//   filter(x, y) = sum_t weight_t * taps_t[x] * taps_t[y], each taps_t summing to 1 and the
//   weights summing to 1, so the whole 2D filter sums to 1 (a constant stays constant).
struct CsfFilter {
    struct Term {
        double weight = 0.0;
        std::vector<double> taps;  // 2r + 1, symmetric
    };
    std::vector<Term> terms;
};

// The paper models each channel's CSF in the spatial domain as
//   S(x) = a1 sqrt(pi / b1) exp(-pi^2 x^2 / b1) + a2 sqrt(pi / b2) exp(-pi^2 x^2 / b2),
// x the distance in degrees of visual angle, sampled at 1 / ppd degrees on the square
// [-r, r]^2 with r = ceil(3 sqrt(b_max / (2 pi^2)) ppd), b_max = 0.04 the widest b of all three
// channels (3 standard deviations of the widest Gaussian), and normalised to sum 1.
// Parameters (FLIP paper, colour pipeline; checked against NVlabs/flip):
//   achromatic  a1 = 1,    b1 = 0.0047, a2 = 0,    b2 = 1e-5
//   red-green   a1 = 1,    b1 = 0.0053, a2 = 0,    b2 = 1e-5
//   blue-yellow a1 = 34.1, b1 = 0.04,   a2 = 13.5, b2 = 0.025
// The 2D exponential factors into x and y parts, so each Gaussian is applied as two 1D passes;
// terms with a = 0 vanish. At 67 pixels per degree r = 10 (21 taps).
CsfFilter csf_filter(OpponentChannel channel, double pixels_per_degree);

// The CSF filter's radius r in pixels (the same for all three channels).
int csf_radius(double pixels_per_degree);

// Filters one plane with the channel's filter.
Plane apply_csf(const Plane& in, const CsfFilter& filter);

}  // namespace vkw::metrics::flip
