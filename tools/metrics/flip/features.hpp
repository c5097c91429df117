// FLIP's feature pipeline (FLIP paper, Andersson et al. 2020): edges and points of the
// achromatic channel, and the feature error Delta E_f.
#pragma once

#include <vector>

#include "tools/metrics/flip/plane.hpp"

namespace vkw::metrics::flip {

// 1D factors of the detectors. The paper's 2D kernels are a derivative of a Gaussian of
// standard deviation sigma = 0.5 w ppd, w = 0.082 degrees (the peak-to-trough width of the
// human edge detector, 2 sigma), sampled on [-r, r]^2, r = ceil(3 sigma):
//   edge   d/dx:   -x g(x) g(y);   point  d^2/dx^2:  (x^2 / sigma^2 - 1) g(x) g(y),
// g(t) = exp(-t^2 / (2 sigma^2)), normalised so the positive weights sum to 1 and the negative
// ones to -1. Both factor into an x part times g(y), and their sign depends on x alone, so the
// normalised 2D kernel is (x part normalised alike) times (g normalised to sum 1): exactly
// the paper's kernel, applied in two 1D passes. At 67 ppd sigma = 2.747, r = 9 (19 taps).
struct FeatureKernels {
    std::vector<double> gaussian;  // g, sum 1
    std::vector<double> edge;      // positive part sums to 1, negative part to -1
    std::vector<double> point;     // likewise
};
FeatureKernels feature_kernels(double pixels_per_degree);

// Per pixel, the magnitude of the edge response (the gradient, x and y detectors) and of the
// point response, of the normalised achromatic plane (values in [0, 1]).
struct FeatureMagnitudes {
    Plane edge;
    Plane point;
};
FeatureMagnitudes detect_features(const Plane& achromatic, const FeatureKernels& kernels);

// Delta E_f = ((1 / sqrt 2) max(| |edge_t| - |edge_r| |, | |point_t| - |point_r| |))^qf,
// qf = 0.5; in [0, 1] because each magnitude lies in [0, sqrt 2] for inputs in [0, 1].
double feature_error(double edge_test, double edge_reference, double point_test, double point_reference);

}  // namespace vkw::metrics::flip
