// shaders/water/glitter_lobe.glsl, run on the device by shaders/tests/glitter_sweep.comp: the sun's
// glitter lobe (docs/model.md section 1, "Sun glitter") reflects exactly the flux its facets
// intercept, its transmission lobe lets through exactly the flux they transmit, and both tend to the
// flat surface's mirror and refraction as the slopes' variance goes to 0.
#include "tests/optics/glitter_facets.hpp"
#include "tests/support/compute_runner.hpp"
#include "tests/support/gpu_test.hpp"

#include <glm/glm.hpp>
#include <shader_structs/tests/glitter_sweep.comp.hpp>

#include <cmath>
#include <numbers>

namespace vkw::test {
namespace {

constexpr double kIor = kGlitterIor;

// tests/glitter_sweep.comp's push block, generated from its SPIR-V (centre.w: the half width;
// covariance.w: the ior).
using Push = glsl::glitter_sweep_comp::Params;

struct LobeIntegral {
    double flux = 0.0;      // the integral of L o_y over the eye's directions
    glm::dvec3 centroid{};  // the directions' mean, weighted by L o_y
};

class GlitterLobe : public GpuTest {
protected:
    LobeIntegral integrate(const Push& push) {
        const std::vector<float> v = run_compute(context(), "tests/glitter_sweep.comp", &push, sizeof push,
                                                 size_t{push.n} * push.n * 4, (push.n * push.n + 63) / 64);
        LobeIntegral result;
        for (size_t k = 0; k < size_t{push.n} * push.n; ++k) {
            const double value = v[4 * k];
            EXPECT_TRUE(std::isfinite(value) && value >= 0.0) << k;
            result.flux += value;
            result.centroid += value * glm::dvec3(v[4 * k + 1], v[4 * k + 2], v[4 * k + 3]);
        }
        result.centroid /= result.flux;
        return result;
    }

    // The lobe's flux over the eye's whole hemisphere (the upper one for the reflection, the lower
    // one for the transmission) against facet_flux, for a low and a high source, a level and a
    // tilted mean, the ocean's anisotropic slopes and isotropic ones, within 1e-3.
    void expect_facet_fluxes(Lobe lobe) {
        const glm::dvec3 covariances[] = {{0.0141, 0.0034, 0.0064}, {0.005, 0.0, 0.005}};
        const glm::dvec2 means[] = {{0.0, 0.0}, {0.1, -0.05}};
        const uint32_t mode = lobe == Lobe::Transmitted ? 2u : 0u;
        for (const double elevation : {15.0, 45.0}) {
            for (const glm::dvec3& s : covariances) {
                for (const glm::dvec2& mean : means) {
                    const glm::dvec3 l = direction(elevation, 30.0);
                    const Push push{glm::vec4(glm::vec3(l), 0.0f),
                                    glm::vec4(0.0f),
                                    glm::vec4(glm::vec3(s), float(kIor)),
                                    glm::vec2(mean),
                                    2040,
                                    mode};
                    const double expected = facet_flux(l, mean, s, lobe);
                    EXPECT_NEAR(integrate(push).flux, expected, 1e-3 * expected)
                        << "elevation " << elevation << ", S_xx " << s.x << ", mean " << mean.x << ", " << mean.y;
                }
            }
        }
    }

    // As the variance falls to 0, the lobe's flux tends to the flat facet's, F or T at (l.n) times
    // (l.n) / n_y for the mean's normal n, at second order in the slopes' spread, and its centroid to
    // the facet's mirrored or refracted direction `flat`, within 2 sigma. Integrated over a patch
    // +-`half_width` sigma wide around it, in 1024^2 cells.
    void expect_flat_limit(Lobe lobe, const glm::dvec3& l, const glm::dvec2& mean, const glm::dvec3& flat,
                           double half_width) {
        const glm::dvec3 n = normal_of_slope(mean);
        const double f = reflectance(glm::dot(l, n), 1.0, kIor);
        const double flat_flux = (lobe == Lobe::Transmitted ? 1.0 - f : f) * glm::dot(l, n) / n.y;
        double previous_error = INFINITY;
        for (const double variance : {1e-4, 1e-5, 1e-6}) {
            const double sigma = std::sqrt(variance);
            const Push push{glm::vec4(glm::vec3(l), 0.0f),
                            glm::vec4(glm::vec3(flat), float(half_width * sigma)),
                            glm::vec4(float(variance), 0.0f, float(variance), float(kIor)),
                            glm::vec2(mean),
                            1024,
                            lobe == Lobe::Transmitted ? 3u : 1u};
            const LobeIntegral integral = integrate(push);
            const double error = std::abs(integral.flux / flat_flux - 1.0);
            EXPECT_LT(error, 30.0 * variance + 1e-4) << "variance " << variance;
            EXPECT_LE(error, previous_error + 1e-4) << "variance " << variance;
            previous_error = error;
            const double centroid_angle = std::acos(std::min(1.0, glm::dot(glm::normalize(integral.centroid), flat)));
            EXPECT_LT(centroid_angle, 2.0 * sigma) << "variance " << variance;
        }
    }
};

// Over the whole hemisphere of eye directions (2040^2 cells, within the dispatch limit of 65535
// groups of 64: 0.003 rad in azimuth, the lobes below
// are 0.1 rad wide or more, so the midpoint rule's error is below 1e-4), for a low and a high
// source, a level and a tilted mean, the ocean's anisotropic slopes and isotropic ones. The shader
// computes each value in fp32 (about 20 roundings: 1e-6 relative); the host sums in double.
TEST_F(GlitterLobe, ReflectsExactlyTheFluxTheFacetsIntercept) { expect_facet_fluxes(Lobe::Reflected); }

// As the variance falls to 0 the lobe tends to the mirror: its flux to the mirror's,
// F(l.n) (l.n) / n_y for the mean's normal n, and its centroid to the mirrored direction. Integrated
// over a patch +-20 sigma wide around the mirrored direction (the lobe's directions spread by
// 2 sigma per axis), in 1024^2 cells of 0.04 sigma.
TEST_F(GlitterLobe, TendsToTheMirrorAsTheVarianceVanishes) {
    const glm::dvec3 l = direction(20.0, -40.0);
    const glm::dvec2 mean(0.05, 0.08);
    const glm::dvec3 n = normal_of_slope(mean);
    expect_flat_limit(Lobe::Reflected, l, mean, 2.0 * glm::dot(l, n) * n - l, 20.0);
}

// The transmission lobe, over the eye's whole lower hemisphere (mode 2), as the reflection lobe
// above: the same grid, sources, means and covariances, and the same 1e-3 bound (the midpoint
// rule's error below 1e-4 and fp32's 1e-6). A facet's tilt turns the refracted ray by 1 - k times
// itself, k = cos(theta_i) / (n cos(theta_t)): 0.38 to 0.72 here, so the narrowest lobe (S 0.005,
// the source 45 degrees up) has a standard deviation of 0.027 rad, about 16 cells of the grid.
TEST_F(GlitterLobe, TransmitsExactlyTheFluxTheFacetsLetThrough) { expect_facet_fluxes(Lobe::Transmitted); }

// As the variance falls to 0 the transmission lobe tends to the flat facet's refraction: its flux to
// T(l.n) (l.n) / n_y for the mean's normal n, its centroid to the refracted direction. The refracted
// ray turns by about (1 - 1/n) times a facet's tilt, so the patch is +-8 sigma wide (1024^2 cells of
// 0.016 sigma); the flux and centroid bounds are the reflection's.
TEST_F(GlitterLobe, TendsToTheRefractionAsTheVarianceVanishes) {
    const glm::dvec3 l = direction(35.0, -40.0);
    const glm::dvec2 mean(0.05, 0.08);
    expect_flat_limit(Lobe::Transmitted, l, mean, refracted(l, normal_of_slope(mean), kIor), 8.0);
}

}  // namespace
}  // namespace vkw::test
