// shaders/common/medium.glsl's single scattering along a view ray (docs/model.md
// section 6), run on the device over 9720 cases (g = 0, 0.9 and -0.3; rays from below
// and from above the horizontal; 1 + c = 0 and +-1e-3 around it; sigma_t from 1e-4 to
// 100 per metre), against the double-precision closed form of the reference renderer
// (tools/reference/optics.cpp), evaluated at the very inputs the shader used.
#include "tests/support/compute_runner.hpp"
#include "tests/support/gpu_test.hpp"
#include "tools/reference/optics.hpp"

#include <shader_structs/tests/in_scatter_sweep.comp.hpp>

#include <cmath>

namespace vkw::test {
namespace {

constexpr uint32_t kCases = 3 * 4 * 15 * 2 * 3 * 3 * 3;
constexpr int kStride = 24;

// tests/in_scatter_sweep.comp's push block, generated from its SPIR-V.
using Push = glsl::in_scatter_sweep_comp::Params;

// Relative fp32 error bound of the shader's result for one channel. Sources, each in
// units of 2^-24:
// - every exp(a): GLSL's precision for exp is 3 + 2|a| ulp, plus ~2|a| for the
//   rounding of its argument: 3 + 4|a|, for a = sigma_t s, tau0 and tau0 + x;
// - 1 + c near 0: its absolute rounding error ~2(1 + |c|) moves x by sigma_t s times
//   that; (1 - e^-x)/x has slope <= 1/2 and is ~1 there, so it counts at half weight;
// - (1 - e^-x)/x by division for x >= 0.1 amplifies the error of e^-x by at most
//   1 / (1 - e^-0.1) = 10.5, i.e. up to 10.5 (3 + 4 x) while e^-x matters: capped at 100;
// - the phase function's peak: d ln p / d cos(a) = 3g / (1 + g^2 - 2g cos a) times the
//   dot product's absolute error of ~3 ulp;
// - about 20 further multiplies, divides and adds.
double relative_bound(double sigma_t, double s, double tau0, double x, double c, double g, double cos_alpha) {
    const double peak = 3.0 * std::abs(g) / (1.0 + g * g - 2.0 * g * cos_alpha);
    const double ulps =
        (3 + 4 * sigma_t * s) + (3 + 4 * (tau0 + std::abs(x))) + sigma_t * s * (1 + std::abs(c)) + 100 + 3 * peak + 20;
    return ulps * std::ldexp(1.0, -24);
}

using InScatterShader = GpuTest;

TEST_F(InScatterShader, MatchesTheClosedFormInEveryCase) {
    Push push{kCases, 1.333f};
    const std::vector<float> v = run_compute(context(), "tests/in_scatter_sweep.comp", &push, sizeof push,
                                             size_t{kCases} * kStride, (kCases + 63) / 64);
    int near_zero_c = 0;
    for (uint32_t i = 0; i < kCases; ++i) {
        const float* k = &v[size_t{i} * kStride];
        for (int channel = 0; channel < 3; ++channel) {
            ref::InScatterInput in;
            in.g = k[0];
            in.z0 = k[1];
            in.s = k[2];
            in.view_direction = {k[3], k[4], k[5]};
            in.refracted_sun = {k[6], k[7], k[8]};
            in.sigma_t = k[9 + channel];
            in.sigma_s = k[12 + channel];
            in.e_perp0 = k[15 + channel];
            in.l_behind = k[18 + channel];
            const double got = k[21 + channel];
            ASSERT_TRUE(std::isfinite(got)) << "case " << i;
            ASSERT_GE(got, 0.0) << "case " << i;
            const double expected = ref::water_path_radiance(in);
            const double cos_t = -in.refracted_sun.y;
            const double c = -in.view_direction.y / cos_t;
            if (std::abs(1.0 + c) < 2e-3) ++near_zero_c;
            const double tau0 = in.sigma_t * in.z0 / cos_t;
            const double x = in.sigma_t * in.s * (1.0 + c);
            const double bound =
                relative_bound(in.sigma_t, in.s, tau0, x, c, in.g, glm::dot(in.refracted_sun, -in.view_direction));
            // Values below fp32's normal range flush to zero on the device (1.2e-38):
            // an absolute floor of 1e-37 covers that and nothing else.
            EXPECT_NEAR(got, expected, bound * expected + 1e-37)
                << "case " << i << " channel " << channel << " g " << in.g << " z0 " << in.z0 << " s " << in.s
                << " v.y " << in.view_direction.y << " sigma_t " << in.sigma_t << " 1+c " << 1 + c;
        }
    }
    EXPECT_GT(near_zero_c, 100);  // the 1 + c ~ 0 cases ran
}

TEST(in_scatter_reference, SpecialCasesOfPhysicsSection6) {
    // Horizontal ray at depth z (c = 0): L = L_b e^{-st s} + ss p E(z) (1 - e^{-st s}) / st.
    ref::InScatterInput in{0.2, 0.5, 0.0, 1.0, 3.0, {1, 0, 0}, {0, -1, 0}, 2.0, 0.1};
    const double p = ref::henyey_greenstein(0.0, 0.0);
    const double e = 2.0 * std::exp(-0.5 * 1.0);
    EXPECT_NEAR(ref::water_path_radiance(in), 0.1 * std::exp(-1.5) + 0.2 * p * e * (1 - std::exp(-1.5)) / 0.5, 1e-15);
    // Vertical ray down from the surface under a vertical sun: c = 1, cos(alpha) = -1
    // (back-scatter, g = 0.9): L = ss p(-1) E0 (1 - e^{-2 st s}) / (2 st).
    in = {0.2, 0.5, 0.9, 0.0, 3.0, {0, -1, 0}, {0, -1, 0}, 2.0, 0.0};
    EXPECT_NEAR(ref::water_path_radiance(in),
                0.2 * ref::henyey_greenstein(-1.0, 0.9) * 2.0 * (1 - std::exp(-3.0)) / 1.0, 1e-15);
    // HG integrates to 1 over the sphere (midpoint rule in cos: exact to ~1e-7 here).
    for (double g : {0.0, 0.9, -0.3}) {
        double sum = 0;
        const int n = 400000;
        for (int j = 0; j < n; ++j) sum += ref::henyey_greenstein(-1.0 + (j + 0.5) * 2.0 / n, g);
        EXPECT_NEAR(2 * 3.14159265358979323846 * sum * 2.0 / n, 1.0, 1e-6) << "g " << g;
    }
    // T_hemi(1.333) = 0.93359 (docs/model.md section 1, printed to 5 decimals).
    EXPECT_NEAR(ref::hemispherical_transmittance(1.333), 0.93359, 5e-6);
    EXPECT_NEAR(ref::hemispherical_transmittance(1.0), 1.0, 1e-9);
}

}  // namespace
}  // namespace vkw::test
