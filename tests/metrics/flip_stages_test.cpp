// FLIP's stages one at a time: filters, colour error mapping, tone mapper, exposure range.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numeric>
#include <vector>

#include "engine/image/tone_curve.hpp"
#include "tests/metrics/metrics_test_support.hpp"
#include "tools/metrics/flip/colour_spaces.hpp"
#include "tools/metrics/flip/convolution.hpp"
#include "tools/metrics/flip/csf_filters.hpp"
#include "tools/metrics/flip/features.hpp"
#include "tools/metrics/flip/hdr_flip.hpp"

namespace vkw::metrics {
namespace {

double sum(const std::vector<double>& v) { return std::accumulate(v.begin(), v.end(), 0.0); }
double sum_if(const std::vector<double>& v, bool positive) {
    double s = 0.0;
    for (double k : v) s += (k > 0.0) == positive ? k : 0.0;
    return s;
}

TEST(metrics_flip_stages, CsfFiltersAreNormalisedSumsOfGaussians) {
    // r = ceil(3 sqrt(0.04 / (2 pi^2)) 67) = ceil(9.05) = 10.
    EXPECT_EQ(flip::csf_radius(kFlipPixelsPerDegree), 10);
    const flip::OpponentChannel channels[] = {flip::OpponentChannel::Achromatic, flip::OpponentChannel::RedGreen,
                                              flip::OpponentChannel::BlueYellow};
    const std::size_t expected_terms[] = {1, 1, 2};  // a2 = 0 for the first two
    for (int c = 0; c < 3; ++c) {
        const flip::CsfFilter filter = flip::csf_filter(channels[c], kFlipPixelsPerDegree);
        ASSERT_EQ(filter.terms.size(), expected_terms[c]);
        double weights = 0.0;
        for (const auto& term : filter.terms) {
            ASSERT_EQ(term.taps.size(), 21u);
            EXPECT_NEAR(sum(term.taps), 1.0, 1e-15);
            for (std::size_t i = 0; i < 21; ++i) EXPECT_EQ(term.taps[i], term.taps[20 - i]);
            weights += term.weight;
        }
        EXPECT_NEAR(weights, 1.0, 1e-15);
    }
    // Blue-yellow by hand: a term's weight is a sqrt(pi / b) S^2, S the sum of its 21 samples
    // of exp(-x^2 / (2 s^2)), s = ppd sqrt(b / (2 pi^2)) pixels (3.02 and 2.39 here). By the
    // midpoint rule S = the integral over [-10.5, 10.5] = sqrt(2 pi) s erf(10.5 / (s sqrt 2)),
    // up to ~1e-5 relative (the end-point term g'(10.5) / 24 over S), so the ratio of the two
    // weights holds to 1e-4 relative.
    constexpr double pi = 3.14159265358979323846;
    auto weight = [&](double a, double b) {
        const double s = kFlipPixelsPerDegree * std::sqrt(b / (2.0 * pi * pi));
        const double integral = std::sqrt(2.0 * pi) * s * std::erf(10.5 / (s * std::sqrt(2.0)));
        return a * std::sqrt(pi / b) * integral * integral;
    };
    const flip::CsfFilter by = flip::csf_filter(flip::OpponentChannel::BlueYellow, kFlipPixelsPerDegree);
    const double expected = weight(34.1, 0.04) / weight(13.5, 0.025);
    EXPECT_NEAR(by.terms[0].weight / by.terms[1].weight, expected, 1e-4 * expected);
}

TEST(metrics_flip_stages, FeatureKernelsHaveUnitSignedParts) {
    // sigma = 0.5 * 0.082 * 67 = 2.747, r = ceil(8.24) = 9.
    const flip::FeatureKernels k = flip::feature_kernels(kFlipPixelsPerDegree);
    ASSERT_EQ(k.gaussian.size(), 19u);
    ASSERT_EQ(k.edge.size(), 19u);
    ASSERT_EQ(k.point.size(), 19u);
    EXPECT_NEAR(sum(k.gaussian), 1.0, 1e-15);
    EXPECT_NEAR(sum_if(k.edge, true), 1.0, 1e-15);
    EXPECT_NEAR(sum_if(k.edge, false), -1.0, 1e-15);
    EXPECT_NEAR(sum_if(k.point, true), 1.0, 1e-15);
    EXPECT_NEAR(sum_if(k.point, false), -1.0, 1e-15);
    for (std::size_t i = 0; i < 19; ++i) {
        // The two halves are normalised by separately accumulated sums: equal to a few ulp.
        EXPECT_DOUBLE_EQ(k.edge[i], -k.edge[18 - i]);  // odd: a derivative
        EXPECT_EQ(k.point[i], k.point[18 - i]);        // even: a second derivative
    }
    EXPECT_GT(k.edge[0 + 5], 0.0);  // -x g(x) is positive left of the centre
    EXPECT_LT(k.point[9], 0.0);     // the second derivative's centre is negative
}

// --- The separable filters against the paper's 2D kernels, built and applied directly ---

// out(x, y) = sum k(i, j) in(clamp(x + i), clamp(y + j)), k of size (2r + 1)^2 indexed [j][i].
flip::Plane correlate_2d(const flip::Plane& in, const std::vector<std::vector<double>>& k) {
    const int r = static_cast<int>(k.size() / 2);
    flip::Plane out(in.width, in.height);
    for (int y = 0; y < in.height; ++y) {
        for (int x = 0; x < in.width; ++x) {
            double s = 0.0;
            for (int j = -r; j <= r; ++j) {
                for (int i = -r; i <= r; ++i) {
                    const int xx = std::clamp(x + i, 0, in.width - 1), yy = std::clamp(y + j, 0, in.height - 1);
                    s += k[j + r][i + r] * in[static_cast<std::size_t>(yy * in.width + xx)];
                }
            }
            out[static_cast<std::size_t>(y * in.width + x)] = static_cast<float>(s);
        }
    }
    return out;
}

// A deterministic 31 x 27 plane of values in [0, 1] with edges and isolated points.
flip::Plane test_plane() {
    flip::Plane p(31, 27);
    unsigned state = 12345u;
    for (std::size_t i = 0; i < p.size(); ++i) {
        state = state * 1664525u + 1013904223u;
        p[i] = static_cast<float>(state >> 8) / static_cast<float>(1u << 24);
    }
    return p;
}

// Signed-part normalisation of a 2D kernel, as the paper states it.
void normalise_2d(std::vector<std::vector<double>>& k) {
    double positive = 0.0, negative = 0.0;
    for (const auto& row : k) {
        for (double v : row) (v > 0.0 ? positive : negative) += v;
    }
    for (auto& row : k) {
        for (double& v : row) v /= v > 0.0 ? positive : -negative;
    }
}

TEST(metrics_flip_stages, SeparableCsfEqualsThePapers2dKernel) {
    constexpr double pi = 3.14159265358979323846;
    const double ppd = kFlipPixelsPerDegree;
    const int r = flip::csf_radius(ppd);
    // Blue-yellow, the two-Gaussian channel: S(x, y) = sum a sqrt(pi / b) exp(-pi^2 (x^2 + y^2) / b).
    std::vector<std::vector<double>> k(2 * r + 1, std::vector<double>(2 * r + 1));
    double total = 0.0;
    for (int j = -r; j <= r; ++j) {
        for (int i = -r; i <= r; ++i) {
            const double d2 = (i * i + j * j) / (ppd * ppd);
            k[j + r][i + r] = 34.1 * std::sqrt(pi / 0.04) * std::exp(-pi * pi * d2 / 0.04) +
                              13.5 * std::sqrt(pi / 0.025) * std::exp(-pi * pi * d2 / 0.025);
            total += k[j + r][i + r];
        }
    }
    for (auto& row : k) {
        for (double& v : row) v /= total;
    }
    const flip::Plane in = test_plane();
    const flip::Plane direct = correlate_2d(in, k);
    const flip::Plane separable = flip::apply_csf(in, flip::csf_filter(flip::OpponentChannel::BlueYellow, ppd));
    for (std::size_t i = 0; i < in.size(); ++i) ASSERT_NEAR(separable[i], direct[i], 1e-6) << i;
}

TEST(metrics_flip_stages, SeparableFeaturesEqualThePapers2dKernels) {
    const double sigma = 0.5 * 0.082 * kFlipPixelsPerDegree;
    const int r = static_cast<int>(std::ceil(3.0 * sigma));
    std::vector<std::vector<double>> edge(2 * r + 1, std::vector<double>(2 * r + 1)), point = edge;
    for (int j = -r; j <= r; ++j) {
        for (int i = -r; i <= r; ++i) {
            const double g = std::exp(-(i * i + j * j) / (2.0 * sigma * sigma));
            edge[j + r][i + r] = -i * g;
            point[j + r][i + r] = (i * i / (sigma * sigma) - 1.0) * g;
        }
    }
    normalise_2d(edge);
    normalise_2d(point);
    auto transposed = [](std::vector<std::vector<double>> k) {
        for (std::size_t a = 0; a < k.size(); ++a) {
            for (std::size_t b = 0; b < a; ++b) std::swap(k[a][b], k[b][a]);
        }
        return k;
    };
    const flip::Plane in = test_plane();
    const flip::Plane ex = correlate_2d(in, edge), ey = correlate_2d(in, transposed(edge));
    const flip::Plane px = correlate_2d(in, point), py = correlate_2d(in, transposed(point));
    const flip::FeatureMagnitudes f = flip::detect_features(in, flip::feature_kernels(kFlipPixelsPerDegree));
    for (std::size_t i = 0; i < in.size(); ++i) {
        ASSERT_NEAR(f.edge[i], std::hypot(ex[i], ey[i]), 1e-6) << i;
        ASSERT_NEAR(f.point[i], std::hypot(px[i], py[i]), 1e-6) << i;
    }
}

TEST(metrics_flip_stages, CorrelationClampsEdgesAndKeepsConstants) {
    flip::Plane impulse(7, 1);
    impulse[3] = 1.0f;
    const std::vector<double> kernel{1.0, 2.0, 4.0};
    const flip::Plane out = flip::correlate(impulse, kernel, flip::Axis::X);
    // out(x) = sum_i k[i + 1] in(x + i): the impulse at 3 is seen from x = 4 (i = -1), 3, 2 (i = 1).
    const std::vector<float> expected{0, 0, 4, 2, 1, 0, 0};
    EXPECT_EQ(out.values, expected);
    flip::Plane constant(5, 4);
    std::fill(constant.values.begin(), constant.values.end(), 0.75f);
    const flip::Plane column = flip::correlate(constant, std::vector<double>{0.25, 0.5, 0.25}, flip::Axis::Y);
    for (float v : column.values) EXPECT_EQ(v, 0.75f);
}

TEST(metrics_flip_stages, ColourErrorMapping) {
    // c_max: the Hunt-adjusted distance of green and blue, to the power 0.7.
    const double c_max =
        std::pow(flip::hyab(flip::hunt_adjusted_lab({0, 1, 0}), flip::hunt_adjusted_lab({0, 0, 1})), 0.7);
    EXPECT_EQ(flip::colour_error(0.0), 0.0);
    EXPECT_NEAR(flip::colour_error(std::pow(c_max, 1.0 / 0.7)), 1.0, 1e-12);
    const double knee = std::pow(0.4 * c_max, 1.0 / 0.7);  // the HyAB distance at the knee
    EXPECT_NEAR(flip::colour_error(knee * (1 - 1e-9)), 0.95, 1e-8);
    EXPECT_NEAR(flip::colour_error(knee), 0.95, 1e-12);
}

TEST(metrics_flip_stages, ToneMapIsAcesNarkowiczOfPointSixX) {
    for (double x : {0.01, 0.1, 0.5, 1.0, 2.0, 5.0, 20.0}) {
        EXPECT_NEAR(hdr_flip_tone_map(x), aces_narkowicz(static_cast<float>(0.6 * x)), 1e-6) << x;
    }
    EXPECT_EQ(hdr_flip_tone_map(0.0), 0.0);
    EXPECT_EQ(hdr_flip_tone_map(-3.0), 0.0);
    EXPECT_EQ(hdr_flip_tone_map(1e30), 1.0);
    const double x = hdr_flip_inverse_tone_map(0.85);
    EXPECT_NEAR(x, 2.1189, 1e-4);  // by hand: positive root of 0.16002 x^2 - 0.2829 x - 0.119
    EXPECT_NEAR(hdr_flip_tone_map(x), 0.85, 1e-12);
}

TEST(metrics_flip_stages, ExposureRangeFromMaxAndMedianLuminance) {
    // Greys (Y = the grey level) 1, 2, 3, 4, 100 (odd count): max 100, median 3.
    const float levels[] = {1.0f, 2.0f, 3.0f, 4.0f, 100.0f};
    const ImageRGBA32F image = test::make_image(5, 1, [&](int x, int) {
        return test::Rgb{levels[x], levels[x], levels[x]};
    });
    const double x = hdr_flip_inverse_tone_map(0.85);
    const FlipExposureRange range = flip_exposure_range(image);
    EXPECT_NEAR(range.start, std::log2(x / 100.0), 1e-12);
    EXPECT_NEAR(range.stop, std::log2(x / 3.0), 1e-12);
    EXPECT_EQ(range.count, 6);  // ceil(log2(100 / 3)) = ceil(5.06)
    EXPECT_NEAR(range.exposure(5), range.stop, 1e-12);

    // Even count: the median is the mean of the middle two, (2 + 3) / 2.
    const ImageRGBA32F even = test::make_image(4, 1, [&](int i, int) {
        const float v = levels[i == 3 ? 4 : i];  // 1, 2, 3, 100
        return test::Rgb{v, v, v};
    });
    EXPECT_NEAR(flip_exposure_range(even).stop, std::log2(x / 2.5), 1e-12);
}

TEST(metrics_flip_stages, ExposureRangeEdgeCases) {
    // Constant reference: start == stop, one exposure.
    const FlipExposureRange constant = flip_exposure_range(test::grey_image(4, 4, 3.0f));
    EXPECT_EQ(constant.count, 1);
    EXPECT_NEAR(constant.start, std::log2(hdr_flip_inverse_tone_map(0.85) / 3.0), 1e-12);
    // Black: exposure 0 only.
    const FlipExposureRange black = flip_exposure_range(test::grey_image(4, 4, 0.0f));
    EXPECT_EQ(black.start, 0.0);
    EXPECT_EQ(black.stop, 0.0);
    EXPECT_EQ(black.count, 1);
    // Mostly black (median 0): the median of the non-black pixels, here 5 = the max.
    const ImageRGBA32F dark = test::make_image(3, 1, [](int x, int) {
        const float v = x == 2 ? 5.0f : 0.0f;
        return test::Rgb{v, v, v};
    });
    const FlipExposureRange range = flip_exposure_range(dark);
    EXPECT_EQ(range.count, 1);
    EXPECT_TRUE(std::isfinite(range.stop));
    // Two points: (1 - 2) stops still gives two exposures.
    const ImageRGBA32F two = test::make_image(3, 1, [](int x, int) {
        const float v = x == 2 ? 2.0f : 1.0f;
        return test::Rgb{v, v, v};
    });
    EXPECT_EQ(flip_exposure_range(two).count, 2);
}

}  // namespace
}  // namespace vkw::metrics
