// Edge and point detection for FLIP's feature pipeline.
#include "tools/metrics/flip/features.hpp"

#include <algorithm>
#include <cmath>

#include "tools/metrics/flip/convolution.hpp"

namespace vkw::metrics::flip {
namespace {

constexpr double kDetectorWidth = 0.082;  // w, degrees
constexpr double kQf = 0.5;               // feature exponent

// Scales the positive weights to sum 1 and the negative ones to sum -1.
void normalise_signed_parts(std::vector<double>& kernel) {
    double positive = 0.0, negative = 0.0;
    for (double k : kernel) (k > 0.0 ? positive : negative) += k;
    for (double& k : kernel) k /= k > 0.0 ? positive : -negative;
}

}  // namespace

FeatureKernels feature_kernels(double pixels_per_degree) {
    const double sigma = 0.5 * kDetectorWidth * pixels_per_degree;
    const int r = static_cast<int>(std::ceil(3.0 * sigma));
    FeatureKernels kernels;
    double sum = 0.0;
    for (int i = -r; i <= r; ++i) {
        const double x = i;
        const double g = std::exp(-x * x / (2.0 * sigma * sigma));
        kernels.gaussian.push_back(g);
        kernels.edge.push_back(-x * g);
        kernels.point.push_back((x * x / (sigma * sigma) - 1.0) * g);
        sum += g;
    }
    for (double& g : kernels.gaussian) g /= sum;
    normalise_signed_parts(kernels.edge);
    normalise_signed_parts(kernels.point);
    return kernels;
}

FeatureMagnitudes detect_features(const Plane& achromatic, const FeatureKernels& kernels) {
    // The x detectors smooth along y, the y detectors along x: share each smoothing pass.
    const Plane smooth_y = correlate(achromatic, kernels.gaussian, Axis::Y);
    const Plane smooth_x = correlate(achromatic, kernels.gaussian, Axis::X);
    const Plane edge_x = correlate(smooth_y, kernels.edge, Axis::X);
    const Plane point_x = correlate(smooth_y, kernels.point, Axis::X);
    const Plane edge_y = correlate(smooth_x, kernels.edge, Axis::Y);
    const Plane point_y = correlate(smooth_x, kernels.point, Axis::Y);
    FeatureMagnitudes out{Plane(achromatic.width, achromatic.height), Plane(achromatic.width, achromatic.height)};
    for (std::size_t i = 0; i < achromatic.size(); ++i) {
        // No overflow to guard against (|responses| <= 1 for inputs in [0, 1]): plain sqrt.
        out.edge[i] = std::sqrt(edge_x[i] * edge_x[i] + edge_y[i] * edge_y[i]);
        out.point[i] = std::sqrt(point_x[i] * point_x[i] + point_y[i] * point_y[i]);
    }
    return out;
}

double feature_error(double edge_test, double edge_reference, double point_test, double point_reference) {
    const double difference = std::max(std::abs(edge_test - edge_reference), std::abs(point_test - point_reference));
    return std::pow(difference / std::sqrt(2.0), kQf);
}

}  // namespace vkw::metrics::flip
