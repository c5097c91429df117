// LDR-FLIP and HDR-FLIP as a whole: exact zeros, the [0, 1] range, uniform images whose answer
// follows from the paper's colour formula by hand, and monotonicity in the perturbation.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "tests/metrics/metrics_test_support.hpp"
#include "tools/metrics/metrics.hpp"

namespace vkw {
namespace {

using metrics::rgb_view;

// --- The colour formula of the FLIP paper, by hand, from published CIE L*a*b* values ---

double lightness_by_hand(double y) {
    return y > std::pow(6.0 / 29.0, 3.0) ? 116.0 * std::cbrt(y) - 16.0 : std::pow(29.0 / 3.0, 3.0) * y;
}

struct Lab {
    double l, a, b;
};

// Hunt adjustment and HyAB as the paper defines them.
double hyab_hunt(const Lab& x, const Lab& y) {
    return std::abs(x.l - y.l) + std::hypot(0.01 * x.l * x.a - 0.01 * y.l * y.a, 0.01 * x.l * x.b - 0.01 * y.l * y.b);
}

double colour_error_by_hand(double hyab) {
    // sRGB green and blue in L*a*b* (D65, Lindbloom's calculator).
    const double c_max = std::pow(hyab_hunt({87.7347, -86.1827, 83.1793}, {32.2970, 79.1875, -107.8602}), 0.7);
    const double d = std::pow(hyab, 0.7);
    return d < 0.4 * c_max ? 0.95 * d / (0.4 * c_max) : 0.95 + 0.05 * (d - 0.4 * c_max) / (0.6 * c_max);
}

// --- Images ---

// Something like a render: a gradient, stripes (edges) and a few highlights far above 1.
ImageRGBA32F scene_like() {
    return test::make_image(48, 40, [](int x, int y) {
        const float base = 0.05f + 0.9f * static_cast<float>(x) / 48.0f;
        const float stripe = ((x / 4 + y / 6) % 2) != 0 ? 0.3f : 0.0f;
        const float highlight = (x == 10 && y == 10) || (x == 30 && y == 25) ? 200.0f : 0.0f;
        return test::Rgb{base + stripe + highlight, 0.5f * base + highlight, 0.2f + stripe + highlight};
    });
}

// Each value times (1 + alpha p), p in {-1, -0.5, 0, 0.5, 1} in a fixed pattern.
ImageRGBA32F perturbed(const ImageRGBA32F& image, float alpha) {
    return test::make_image(image.width, image.height, [&](int x, int y) {
        const float p = static_cast<float>((x * 7 + y * 13) % 5 - 2) / 2.0f;
        const float* c = image.pixel(x, y);
        return test::Rgb{c[0] * (1 + alpha * p), c[1] * (1 - alpha * p), c[2] * (1 + alpha * p)};
    });
}

std::vector<float> ldr_map(const ImageRGBA32F& a, const ImageRGBA32F& b) {
    return metrics::ldr_flip_map(rgb_view(a), rgb_view(b));
}

double hdr_mean(const ImageRGBA32F& a, const ImageRGBA32F& b) {
    return metrics::flip_mean(rgb_view(a), rgb_view(b), test::all_pixels(b), metrics::flip_exposure_range(b));
}

TEST(metrics_flip, IdenticalImagesGiveExactlyZero) {
    const ImageRGBA32F b = scene_like();
    const metrics::FlipExposureRange range = metrics::flip_exposure_range(b);
    ASSERT_GT(range.count, 2);
    for (float e : metrics::hdr_flip_map(rgb_view(b), rgb_view(b), range)) ASSERT_EQ(e, 0.0f);
    for (float e : ldr_map(b, b)) ASSERT_EQ(e, 0.0f);
    EXPECT_EQ(hdr_mean(b, b), 0.0);
}

TEST(metrics_flip, UniformImagesFollowTheColourFormula) {
    // A uniform image has no edges or points (Delta E_f = 0) and the normalised CSF filters keep
    // it uniform, so every pixel's error is the colour error of the two colours. The published
    // L*a*b* values carry 4 decimals and the features a ~1e-8 rounding residue: 2e-4.
    struct Case {
        test::Rgb a, b;
        double expected;
    };
    const double l18 = lightness_by_hand(0.18), l20 = lightness_by_hand(0.2);
    const Case cases[] = {
        // Black against white: HyAB 100, beyond the knee (0.4 c_max = 16.5): 0.9670.
        {{0, 0, 0}, {1, 1, 1}, colour_error_by_hand(100.0)},
        // Greys 0.18 and 0.2: HyAB = dL* = 2.34, below the knee.
        {{0.18f, 0.18f, 0.18f}, {0.2f, 0.2f, 0.2f}, colour_error_by_hand(l20 - l18)},
        // Red against green.
        {{1, 0, 0},
         {0, 1, 0},
         colour_error_by_hand(hyab_hunt({53.2408, 80.0925, 67.2032}, {87.7347, -86.1827, 83.1793}))},
    };
    for (const Case& c : cases) {
        const std::vector<float> map = ldr_map(test::constant_image(24, 20, c.a), test::constant_image(24, 20, c.b));
        for (float e : map) ASSERT_NEAR(e, c.expected, 2e-4);
    }
}

TEST(metrics_flip, UniformHdrGreysAtTheSingleExposure) {
    // Reference grey 3: max = median, so one exposure, which takes 3 to x_0.85 (tone mapped to
    // 0.85). The test grey 6 goes to 2 x_0.85 and through ACES (Narkowicz) of 0.6 times that.
    const ImageRGBA32F b = test::grey_image(24, 20, 3.0f);
    const metrics::FlipExposureRange range = metrics::flip_exposure_range(b);
    ASSERT_EQ(range.count, 1);
    const double x = 0.6 * 2.0 * metrics::hdr_flip_inverse_tone_map(0.85);
    const double tone_mapped = x * (2.51 * x + 0.03) / (x * (2.43 * x + 0.59) + 0.14);
    const double expected = colour_error_by_hand(lightness_by_hand(tone_mapped) - lightness_by_hand(0.85));
    for (float e : metrics::hdr_flip_map(rgb_view(test::grey_image(24, 20, 6.0f)), rgb_view(b), range)) {
        ASSERT_NEAR(e, expected, 2e-4);
    }
}

TEST(metrics_flip, ErrorsLieInZeroOne) {
    // Extreme LDR pairs: checkerboards of primaries, black and white against their inverses.
    const test::Rgb colours[] = {{0, 0, 0}, {1, 1, 1}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {1, 1, 0}};
    for (const test::Rgb& u : colours) {
        for (const test::Rgb& v : colours) {
            const ImageRGBA32F a = test::make_image(24, 20, [&](int x, int y) { return (x + y) % 2 ? u : v; });
            const ImageRGBA32F b = test::make_image(24, 20, [&](int x, int) { return (x / 3) % 2 ? v : u; });
            for (float e : ldr_map(a, b)) {
                ASSERT_GE(e, 0.0f);
                ASSERT_LE(e, 1.0f);
            }
        }
    }
    // HDR: a render against a strongly perturbed copy.
    const ImageRGBA32F b = scene_like();
    const std::vector<float> map =
        metrics::hdr_flip_map(rgb_view(perturbed(b, 0.9f)), rgb_view(b), metrics::flip_exposure_range(b));
    EXPECT_GT(*std::max_element(map.begin(), map.end()), 0.1f);
    for (float e : map) {
        ASSERT_GE(e, 0.0f);
        ASSERT_LE(e, 1.0f);
    }
}

TEST(metrics_flip, LargerPerturbationGivesLargerMean) {
    const ImageRGBA32F b = scene_like();
    double previous = 0.0;
    for (float alpha : {0.01f, 0.03f, 0.1f, 0.3f, 0.9f}) {
        const double mean = hdr_mean(perturbed(b, alpha), b);
        EXPECT_GT(mean, previous) << "alpha " << alpha;
        previous = mean;
    }
    previous = 0.0;
    for (float k : {1.02f, 1.1f, 1.5f, 3.0f}) {
        const double mean = hdr_mean(test::scaled(b, k), b);
        EXPECT_GT(mean, previous) << "scale " << k;
        previous = mean;
    }
}

TEST(metrics_flip, NegativeValuesCountAsZero) {
    const ImageRGBA32F b = test::make_image(24, 20, [](int x, int) {
        return x < 12 ? test::Rgb{0, 0, 0} : test::Rgb{1, 2, 3};
    });
    const ImageRGBA32F a = test::make_image(24, 20, [](int x, int) {
        return x < 12 ? test::Rgb{-1, -5, 0} : test::Rgb{1, 2, 3};
    });
    EXPECT_EQ(hdr_mean(a, b), 0.0);
}

TEST(metrics_flip, MaskedMeanAveragesTheMapOverTheMask) {
    const ImageRGBA32F b = scene_like();
    const ImageRGBA32F a = perturbed(b, 0.2f);
    const ImageRGBA32F mask = test::make_image(b.width, b.height, [](int x, int y) {
        return test::Rgb{(x + y) % 3 == 0 ? 1.0f : 0.0f, 0, 0};
    });
    const metrics::FlipExposureRange range = metrics::flip_exposure_range(b);
    const std::vector<float> map = metrics::hdr_flip_map(rgb_view(a), rgb_view(b), range);
    const std::vector<std::size_t> pixels = metrics::counted_pixels(b.width, b.height, &mask);
    double sum = 0.0;
    for (std::size_t p : pixels) sum += map[p];
    test::expect_relative(metrics::flip_mean(rgb_view(a), rgb_view(b), pixels, range),
                          sum / static_cast<double>(pixels.size()));
}

}  // namespace
}  // namespace vkw
