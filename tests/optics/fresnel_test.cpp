// shaders/common/fresnel.glsl, run on the device by a compute kernel, against an
// independent double-precision Fresnel (the angle form of the equations, not the
// cosine form the shader uses) and against docs/model.md section 2's table:
// R + T = 1, both in [0, 1], 10^4 angles from each side; TIR exactly R = 1 beyond
// the critical angle; the tabulated air-to-water transmittances.
#include "tests/optics/fresnel_angle_form.hpp"
#include "tests/support/compute_runner.hpp"
#include "tests/support/gpu_test.hpp"

#include <shader_structs/tests/fresnel_sweep.comp.hpp>

#include <cmath>
#include <numbers>

namespace vkw::test {
namespace {

constexpr double kIor = 1.333;
constexpr uint32_t kSamples = 10000;
constexpr int kStride = 10;

// Bound on the fp32 error of the shader's R at cos_i. The arithmetic after cos_t
// (a few multiplies, two divisions, squares) costs at most ~16 roundings of 2^-24
// relative to values <= 1. The dominant term is cos_t = sqrt(1 - eta^2 (1 - cos_i^2)):
// 4 roundings give an absolute error eps = 4 * 2^-24 in the radicand, so cos_t is off
// by eps / (2 cos_t), or by at most sqrt(eps) where cos_t ~ 0 (critical angle, grazing);
// R moves by |dR/dcos_t| times that (computed here in double by a central difference).
double fp32_bound(double cos_i, double n_i, double n_t) {
    const double eps = 4.0 * std::ldexp(1.0, -24);
    const double eta = n_i / n_t;
    const double radicand = 1.0 - eta * eta * (1.0 - cos_i * cos_i);
    if (radicand <= eps) return 1.0;  // within rounding of TIR: only R, T in [0, 1] can be checked
    const double cos_t = std::sqrt(radicand);
    const double d_cos_t = std::min(std::sqrt(eps), eps / (2.0 * cos_t));
    auto r_of_cos_t = [&](double c) {
        const double rs = (n_i * cos_i - n_t * c) / (n_i * cos_i + n_t * c);
        const double rp = (n_t * cos_i - n_i * c) / (n_t * cos_i + n_i * c);
        return 0.5 * (rs * rs + rp * rp);
    };
    const double h = 1e-7;
    const double slope = std::abs(r_of_cos_t(cos_t + h) - r_of_cos_t(std::max(0.0, cos_t - h))) / (2 * h);
    return 16.0 * std::ldexp(1.0, -24) + slope * d_cos_t;
}

// tests/fresnel_sweep.comp's push block, generated from its SPIR-V.
using Push = glsl::fresnel_sweep_comp::Params;

constexpr double kTableDeg[7] = {0, 30, 45, 60, 75, 85, 89};
// docs/model.md section 2: air to water, n = 1.333, as printed (5 or 6 decimals).
constexpr double kTableT[7] = {0.979627, 0.97856, 0.97210, 0.94031, 0.78762, 0.41648, 0.10372};

class FresnelShader : public GpuTest {
protected:
    std::vector<float> run() {
        Push push{static_cast<float>(kIor), kSamples, {}};
        for (int k = 0; k < 7; ++k) {
            push.table_cos[k] = static_cast<float>(std::cos(kTableDeg[k] * std::numbers::pi / 180.0));
        }
        const uint32_t total = kSamples + 7;
        return run_compute(context(), "tests/fresnel_sweep.comp", &push, sizeof push, size_t{total} * kStride,
                           (total + 63) / 64);
    }
};

TEST_F(FresnelShader, ExactFresnelFromBothSidesMatchesDoublePrecision) {
    const std::vector<float> v = run();
    int checked_tir = 0;
    for (uint32_t i = 0; i < kSamples; ++i) {
        const float* s = &v[size_t{i} * kStride];
        const double cos_i = s[0];
        for (int side = 0; side < 2; ++side) {
            const double n_i = side == 0 ? 1.0 : kIor, n_t = side == 0 ? kIor : 1.0;
            const double R = s[1 + 2 * side], T = s[2 + 2 * side];
            ASSERT_TRUE(std::isfinite(R) && std::isfinite(T)) << "cos_i " << cos_i << " side " << side;
            EXPECT_GE(R, 0.0);
            EXPECT_LE(R, 1.0);
            EXPECT_GE(T, 0.0);
            EXPECT_LE(T, 1.0);
            // T is computed as 1 - R in fp32: one rounding of a value <= 1.
            EXPECT_NEAR(R + T, 1.0, std::ldexp(1.0, -24)) << "cos_i " << cos_i;
            const double expected = reflectance(cos_i, n_i, n_t);
            if (expected == 1.0 && side == 1 && cos_i < std::sqrt(1.0 - 1.0 / (kIor * kIor)) - 1e-6) {
                // Beyond the critical angle (48.607 degrees) from below: exactly 1 and 0.
                EXPECT_EQ(R, 1.0) << "cos_i " << cos_i;
                EXPECT_EQ(T, 0.0) << "cos_i " << cos_i;
                ++checked_tir;
                continue;
            }
            EXPECT_NEAR(R, expected, fp32_bound(cos_i, n_i, n_t)) << "cos_i " << cos_i << " side " << side;
        }
    }
    EXPECT_GT(checked_tir, 6000);  // cos(48.6 deg) = 0.661: about 66% of the samples are TIR from below
}

TEST_F(FresnelShader, AirToWaterTransmittanceMatchesThePhysicsTable) {
    const std::vector<float> v = run();
    for (int k = 0; k < 7; ++k) {
        const float* s = &v[size_t{kSamples + k} * kStride];
        // The table is printed to 5-6 decimals (rounding <= 5e-6); plus the shader's fp32 bound.
        const double tolerance = 5e-6 + fp32_bound(s[0], 1.0, kIor);
        EXPECT_NEAR(s[2], kTableT[k], tolerance) << kTableDeg[k] << " degrees";
    }
}

TEST_F(FresnelShader, SchlickIsExactAtNormalIncidenceAndTotalInternalReflectionIsExact) {
    const std::vector<float> v = run();
    const float* normal = &v[size_t{kSamples - 1} * kStride];  // cos_i = 1
    const double r0 = std::pow((kIor - 1) / (kIor + 1), 2);
    EXPECT_NEAR(normal[5], r0, 4 * std::ldexp(1.0, -24));  // a few fp32 roundings of values < 1
    EXPECT_NEAR(normal[7], r0, 4 * std::ldexp(1.0, -24));
    for (uint32_t i = 0; i < kSamples; ++i) {
        const float* s = &v[size_t{i} * kStride];
        if (s[3] == 1.0f) {
            EXPECT_EQ(s[7], 1.0f) << "Schlick from below must keep R = 1 under TIR, cos_i " << s[0];
        }
        // Schlick never leaves [0, 1] and stays within 0.06 of exact from the air side
        // (its known worst case for n = 1.333 is about 0.04, near grazing).
        EXPECT_GE(s[5], 0.0f);
        EXPECT_LE(s[5], 1.0f);
        EXPECT_NEAR(s[5], s[1], 0.06) << "cos_i " << s[0];
    }
}

}  // namespace
}  // namespace vkw::test
