// shaders/water/glitter_lobe.glsl, run on the device by shaders/tests/glitter_sweep.comp: the sun's
// glitter lobe (docs/model.md section 1, "Sun glitter") reflects exactly the flux its facets
// intercept, its transmission lobe lets through exactly the flux they transmit, and both tend to the
// flat surface's mirror and refraction as the slopes' variance goes to 0.
#include "tests/optics/fresnel_angle_form.hpp"
#include "tests/support/compute_runner.hpp"
#include "tests/support/gpu_test.hpp"

#include <glm/glm.hpp>
#include <shader_structs/tests/glitter_sweep.comp.hpp>

#include <cmath>
#include <numbers>

namespace vkw::test {
namespace {

constexpr double kIor = 1.333;

// tests/glitter_sweep.comp's push block, generated from its SPIR-V (centre.w: the half width;
// covariance.w: the ior).
using Push = glsl::glitter_sweep_comp::Params;

glm::dvec3 direction(double elevation_deg, double azimuth_deg) {
    const double e = elevation_deg * std::numbers::pi / 180.0, a = azimuth_deg * std::numbers::pi / 180.0;
    return {std::cos(e) * std::sin(a), std::sin(e), -std::cos(e) * std::cos(a)};
}

glm::dvec3 normal_of_slope(const glm::dvec2& z) { return glm::normalize(glm::dvec3(-z.x, 1.0, -z.y)); }

// The direction of the light from l (toward the source, in the air) refracted through a facet of
// normal h into water of index n, by Snell's law in vector form.
glm::dvec3 refracted(const glm::dvec3& l, const glm::dvec3& h, double n) {
    const double cos_i = glm::dot(l, h);
    const double cos_t = std::sqrt(1.0 - (1.0 - cos_i * cos_i) / (n * n));
    return -l / n + (cos_i / n - cos_t) * h;
}

enum class Lobe { Reflected, Transmitted };

// The flux the facets send on per unit source irradiance: the integral over slopes z of
// F(l.h) (l.h) / h_y p(z) (reflected, over the slopes whose mirror sends l upward) or
// T(l.h) (l.h) / h_y p(z) (transmitted, over those whose refraction sends it down), p Gaussian of
// mean `mean` and covariance (S_xx, S_xz, S_zz), by the midpoint rule over +-9 standard deviations of
// each axis in 1201^2 cells (cells of 0.015 sigma: the rule's error on a Gaussian is below 1e-6).
double facet_flux(const glm::dvec3& l, const glm::dvec2& mean, const glm::dvec3& s, Lobe lobe = Lobe::Reflected) {
    const double sx = std::sqrt(s.x), sz = std::sqrt(s.z), det = s.x * s.z - s.y * s.y;
    const int cells = 1201;
    const double dx = 18.0 * sx / cells, dz = 18.0 * sz / cells;
    double flux = 0.0;
    for (int i = 0; i < cells; ++i) {
        for (int j = 0; j < cells; ++j) {
            const glm::dvec2 d(-9.0 * sx + (i + 0.5) * dx, -9.0 * sz + (j + 0.5) * dz);
            const glm::dvec3 h = normal_of_slope(mean + d);
            const double lh = glm::dot(l, h);
            if (!(lh > 0.0)) continue;
            const bool transmitted = lobe == Lobe::Transmitted;
            if (transmitted ? !(refracted(l, h, kIor).y < 0.0) : !((2.0 * lh * h - l).y > 0.0)) continue;
            const double q = (s.z * d.x * d.x - 2.0 * s.y * d.x * d.y + s.x * d.y * d.y) / det;
            const double density = std::exp(-0.5 * q) / (2.0 * std::numbers::pi * std::sqrt(det));
            const double f = reflectance(lh, 1.0, kIor);
            flux += (transmitted ? 1.0 - f : f) * lh / h.y * density * dx * dz;
        }
    }
    return flux;
}

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
};

// Over the whole hemisphere of eye directions (2040^2 cells, within the dispatch limit of 65535
// groups of 64: 0.003 rad in azimuth, the lobes below
// are 0.1 rad wide or more, so the midpoint rule's error is below 1e-4), for a low and a high
// source, a level and a tilted mean, the ocean's anisotropic slopes and isotropic ones. The shader
// computes each value in fp32 (about 20 roundings: 1e-6 relative); the host sums in double.
TEST_F(GlitterLobe, ReflectsExactlyTheFluxTheFacetsIntercept) {
    const glm::dvec3 covariances[] = {{0.0141, 0.0034, 0.0064}, {0.005, 0.0, 0.005}};
    const glm::dvec2 means[] = {{0.0, 0.0}, {0.1, -0.05}};
    for (const double elevation : {15.0, 45.0}) {
        for (const glm::dvec3& s : covariances) {
            for (const glm::dvec2& mean : means) {
                const glm::dvec3 l = direction(elevation, 30.0);
                const Push push{glm::vec4(glm::vec3(l), 0.0f),
                                glm::vec4(0.0f),
                                glm::vec4(glm::vec3(s), float(kIor)),
                                glm::vec2(mean),
                                2040,
                                0};
                const double expected = facet_flux(l, mean, s);
                EXPECT_NEAR(integrate(push).flux, expected, 1e-3 * expected)
                    << "elevation " << elevation << ", S_xx " << s.x << ", mean " << mean.x << ", " << mean.y;
            }
        }
    }
}

// As the variance falls to 0 the lobe tends to the mirror: its flux to the mirror's,
// F(l.n) (l.n) / n_y for the mean's normal n, and its centroid to the mirrored direction. Integrated
// over a patch +-20 sigma wide around the mirrored direction (the lobe's directions spread by
// 2 sigma per axis), in 1024^2 cells of 0.04 sigma.
TEST_F(GlitterLobe, TendsToTheMirrorAsTheVarianceVanishes) {
    const glm::dvec3 l = direction(20.0, -40.0);
    const glm::dvec2 mean(0.05, 0.08);
    const glm::dvec3 n = normal_of_slope(mean);
    const glm::dvec3 mirror = 2.0 * glm::dot(l, n) * n - l;
    const double mirror_flux = reflectance(glm::dot(l, n), 1.0, kIor) * glm::dot(l, n) / n.y;
    double previous_error = INFINITY;
    for (const double variance : {1e-4, 1e-5, 1e-6}) {
        const double sigma = std::sqrt(variance);
        const Push push{glm::vec4(glm::vec3(l), 0.0f),
                        glm::vec4(glm::vec3(mirror), float(20.0 * sigma)),
                        glm::vec4(float(variance), 0.0f, float(variance), float(kIor)),
                        glm::vec2(mean),
                        1024,
                        1};
        const LobeIntegral lobe = integrate(push);
        const double error = std::abs(lobe.flux / mirror_flux - 1.0);
        // The lobe's flux differs from the mirror's at second order in the slopes' spread.
        EXPECT_LT(error, 30.0 * variance + 1e-4) << "variance " << variance;
        EXPECT_LE(error, previous_error + 1e-4) << "variance " << variance;
        previous_error = error;
        const double centroid_angle = std::acos(std::min(1.0, glm::dot(glm::normalize(lobe.centroid), mirror)));
        EXPECT_LT(centroid_angle, 2.0 * sigma) << "variance " << variance;
    }
}

// The transmission lobe, over the eye's whole lower hemisphere (mode 2), as the reflection lobe
// above: the same grid, sources, means and covariances, and the same 1e-3 bound (the midpoint
// rule's error below 1e-4 and fp32's 1e-6). A facet's tilt turns the refracted ray by 1 - k times
// itself, k = cos(theta_i) / (n cos(theta_t)): 0.38 to 0.72 here, so the narrowest lobe (S 0.005,
// the source 45 degrees up) has a standard deviation of 0.027 rad, about 16 cells of the grid.
TEST_F(GlitterLobe, TransmitsExactlyTheFluxTheFacetsLetThrough) {
    const glm::dvec3 covariances[] = {{0.0141, 0.0034, 0.0064}, {0.005, 0.0, 0.005}};
    const glm::dvec2 means[] = {{0.0, 0.0}, {0.1, -0.05}};
    for (const double elevation : {15.0, 45.0}) {
        for (const glm::dvec3& s : covariances) {
            for (const glm::dvec2& mean : means) {
                const glm::dvec3 l = direction(elevation, 30.0);
                const Push push{glm::vec4(glm::vec3(l), 0.0f),
                                glm::vec4(0.0f),
                                glm::vec4(glm::vec3(s), float(kIor)),
                                glm::vec2(mean),
                                2040,
                                2};
                const double expected = facet_flux(l, mean, s, Lobe::Transmitted);
                EXPECT_NEAR(integrate(push).flux, expected, 1e-3 * expected)
                    << "elevation " << elevation << ", S_xx " << s.x << ", mean " << mean.x << ", " << mean.y;
            }
        }
    }
}

// As the variance falls to 0 the transmission lobe tends to the flat facet's refraction: its flux to
// T(l.n) (l.n) / n_y for the mean's normal n, its centroid to the refracted direction. The refracted
// ray turns by about (1 - 1/n) times a facet's tilt, so the patch is +-8 sigma wide (1024^2 cells of
// 0.016 sigma); the flux and centroid bounds are the reflection's.
TEST_F(GlitterLobe, TendsToTheRefractionAsTheVarianceVanishes) {
    const glm::dvec3 l = direction(35.0, -40.0);
    const glm::dvec2 mean(0.05, 0.08);
    const glm::dvec3 n = normal_of_slope(mean);
    const glm::dvec3 through = refracted(l, n, kIor);
    const double flat_flux = (1.0 - reflectance(glm::dot(l, n), 1.0, kIor)) * glm::dot(l, n) / n.y;
    double previous_error = INFINITY;
    for (const double variance : {1e-4, 1e-5, 1e-6}) {
        const double sigma = std::sqrt(variance);
        const Push push{glm::vec4(glm::vec3(l), 0.0f),
                        glm::vec4(glm::vec3(through), float(8.0 * sigma)),
                        glm::vec4(float(variance), 0.0f, float(variance), float(kIor)),
                        glm::vec2(mean),
                        1024,
                        3};
        const LobeIntegral lobe = integrate(push);
        const double error = std::abs(lobe.flux / flat_flux - 1.0);
        EXPECT_LT(error, 30.0 * variance + 1e-4) << "variance " << variance;
        EXPECT_LE(error, previous_error + 1e-4) << "variance " << variance;
        previous_error = error;
        const double centroid_angle = std::acos(std::min(1.0, glm::dot(glm::normalize(lobe.centroid), through)));
        EXPECT_LT(centroid_angle, 2.0 * sigma) << "variance " << variance;
    }
}

}  // namespace
}  // namespace vkw::test
