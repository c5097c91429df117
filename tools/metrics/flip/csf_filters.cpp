// The CSF filters of FLIP's colour pipeline, built as sums of separable Gaussians.
#include "tools/metrics/flip/csf_filters.hpp"

#include <cmath>
#include <numbers>

#include "tools/metrics/flip/convolution.hpp"

namespace vkw::metrics::flip {
namespace {

struct CsfParameters {
    double a1, b1, a2, b2;
};

CsfParameters parameters(OpponentChannel channel) {
    switch (channel) {
        case OpponentChannel::Achromatic: return {1.0, 0.0047, 0.0, 1e-5};
        case OpponentChannel::RedGreen: return {1.0, 0.0053, 0.0, 1e-5};
        case OpponentChannel::BlueYellow: return {34.1, 0.04, 13.5, 0.025};
    }
    return {};
}

constexpr double kWidestB = 0.04;  // the largest b1, b2 over the three channels

}  // namespace

int csf_radius(double pixels_per_degree) {
    constexpr double pi = std::numbers::pi;
    return static_cast<int>(std::ceil(3.0 * std::sqrt(kWidestB / (2.0 * pi * pi)) * pixels_per_degree));
}

CsfFilter csf_filter(OpponentChannel channel, double pixels_per_degree) {
    constexpr double pi = std::numbers::pi;
    const CsfParameters p = parameters(channel);
    const int r = csf_radius(pixels_per_degree);
    const double step = 1.0 / pixels_per_degree;  // degrees per pixel

    // Each term a sqrt(pi/b) g(x) g(y) with g(x) = exp(-pi^2 x^2 / b): its 2D sum is
    // a sqrt(pi/b) (sum g)^2, so with g normalised to sum 1 its weight is that sum over the
    // total of both terms.
    CsfFilter filter;
    double total = 0.0;
    for (const auto& [a, b] : {std::pair{p.a1, p.b1}, std::pair{p.a2, p.b2}}) {
        if (a == 0.0) continue;
        CsfFilter::Term term;
        double sum = 0.0;
        for (int i = -r; i <= r; ++i) {
            const double x = i * step;
            term.taps.push_back(std::exp(-pi * pi * x * x / b));
            sum += term.taps.back();
        }
        for (double& tap : term.taps) tap /= sum;
        term.weight = a * std::sqrt(pi / b) * sum * sum;
        total += term.weight;
        filter.terms.push_back(std::move(term));
    }
    for (CsfFilter::Term& term : filter.terms) term.weight /= total;
    return filter;
}

Plane apply_csf(const Plane& in, const CsfFilter& filter) {
    Plane out(in.width, in.height);
    for (const CsfFilter::Term& term : filter.terms) {
        const Plane part = correlate_separable(in, term.taps, term.taps);
        for (std::size_t i = 0; i < out.size(); ++i) {
            out[i] = static_cast<float>(out[i] + term.weight * part[i]);
        }
    }
    return out;
}

}  // namespace vkw::metrics::flip
