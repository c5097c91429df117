// The in-scatter under waves (tools/reference/caustic_in_scatter.hpp): flat water's beams give
// docs/model.md section 6's closed form on every kind of ray, and under a sine the modulated
// in-scatter along a horizontal ray equals a crude independent estimate (the section-5
// histogram of the sine's refraction map at the ray's depth, integrated along the ray).
#include "tools/reference/caustic_in_scatter.hpp"
#include "engine/scene/scene_loader.hpp"
#include "engine/water/surface.hpp"
#include "tests/reference/sine_profile.hpp"
#include "tests/reference/sine_scene.hpp"
#include "tools/reference/optics.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <string>

namespace vkw::ref {
namespace {

// tests/reference/sine_scene.hpp's sine (wavelength 0.5 m, water 2 m wide, the floor 1 m down)
// in scattering water with a forward-peaked phase function (g = 0.9).
Scene scattering_sine_scene(double amplitude, double sun_elevation_deg) {
    return sine_scene_with_amplitude(amplitude, sun_elevation_deg,
                                     R"({"sigma_a": [0.1, 0.2, 0.4], "sigma_s": [0.3, 0.3, 0.3], "g": 0.9})");
}

TEST(reference_caustic_in_scatter, FlatWaterGivesTheSection6ClosedForm) {
    const Scene scene = scattering_sine_scene(0.0, 60.0);
    const auto surface = make_surface(scene.water->waves, 0.0, 0.0);
    const CausticInScatter in_scatter(scene, *surface, 0.0, {4, 512, 128, 0.0});
    const glm::dvec3 t = *refract(scene.sun.direction, {0.0, 1.0, 0.0}, 1.0 / 1.333);
    const double cos_s = -scene.sun.direction.y, cos_t = -t.y;
    const double e_perp0 = 2.0 * cos_s * (1.0 - fresnel_reflectance(cos_s, 1.0, 1.333)) / cos_t;
    struct Case {
        glm::dvec3 origin, direction;
        double length;
    };
    // Horizontal at two depths, straight down from the surface, rising obliquely, and along the beam.
    for (const Case& ray :
         {Case{{-0.4, -0.5, 0.1}, {1, 0, 0}, 0.8}, Case{{0.0, -0.25, -0.3}, {0, 0, 1}, 0.6},
          Case{{0.1, 0.0, 0.0}, {0, -1, 0}, 1.0},
          Case{{0.2, -0.9, 0.0}, glm::normalize(glm::dvec3(-0.5, 0.6, 0.2)), 1.0}, Case{{0.3, -0.1, 0.0}, t, 0.8}}) {
        SCOPED_TRACE("ray from (" + std::to_string(ray.origin.x) + ", " + std::to_string(ray.origin.y) + ")");
        const glm::dvec3 got = in_scatter.segment_radiance(ray.origin, ray.direction, ray.length, glm::dvec3(0.0));
        for (int c = 0; c < 3; ++c) {
            const double expected = water_path_radiance(
                {0.3, scene.medium.sigma_t()[c], 0.9, -ray.origin.y, ray.length, ray.direction, t, e_perp0, 0.0});
            // The flat beams give the closed-form irradiance to the polygon clipping's rounding
            // (1e-9, floor_caustics_test), so m = 1 within it; the segments' closed forms add up to
            // the whole one to rounding (1e-13 for a few hundred terms).
            EXPECT_NEAR(got[c], expected, 1e-8 * expected) << "channel " << c;
        }
    }
}

TEST(reference_caustic_in_scatter, SineAgreesWithAnIndependentEstimate) {
    // A k = 0.3, vertical sun: focal lines below the first cusp at d* = 0.35 m (docs/model.md 5).
    const double wavelength = 0.5, k = 2.0 * std::numbers::pi / wavelength, amplitude = 0.3 / k;
    const Scene scene = scattering_sine_scene(amplitude, 90.0);
    const auto surface = make_surface(scene.water->waves, 0.0, 0.0);
    const CausticInScatter in_scatter(scene, *surface, amplitude, {9, 512, 1024, 0.0});
    // Horizontal rays along x at two planes' depths (past the cusp and near the floor), over a
    // quarter wavelength around the crest at x = 1/8 m (where the beams focus: over whole
    // wavelengths the modulation would average out to the flat in-scatter, energy being
    // conserved), from x = 1/16 m, a texel edge (4 m + 1/16 m = 260 texels of 1/64 m).
    for (size_t plane : {3u, 7u}) {
        const double depth = in_scatter.plane_depths()[plane];
        SCOPED_TRACE("depth " + std::to_string(depth));
        const double x0 = 0.0625, length = 0.25 * wavelength;
        const glm::dvec3 got = in_scatter.segment_radiance({x0, -depth, 0.0}, {1, 0, 0}, length, glm::dvec3(0.0));
        // Independent: the histogram of the sine's refraction map at this depth (E_s = 1 there,
        // so scaled by the sun's 2), texel by texel along the ray: sigma_s p(cos alpha) E_h / cos(theta_t)
        // exp(-sigma_t u) integrated exactly over each texel, cos(theta_t) = 1 and cos(alpha) = 0.
        const int texels = 512;
        const double floor_extent = 4.0, texel = 2.0 * floor_extent / texels;
        for (int c = 0; c < 3; ++c) {
            const double sigma_t = scene.medium.sigma_t()[c];
            // Beams that land on the ray entered within 0.1 m of it (slopes up to A k = 0.3 turn
            // them by at most 0.075 rad, less than 1 m deep): the surface over |x| < 0.5 m holds them all.
            const std::vector<double> profile =
                sine_profile(amplitude, k, depth, sigma_t, 0.5, floor_extent, texels, 1.333);
            double expected = 0.0;
            for (int i = 0; i < int(std::lround(length / texel)); ++i) {
                const double u0 = i * texel;
                const int bin = static_cast<int>(std::floor((x0 + u0 + 0.5 * texel + floor_extent) / texel));
                expected += 0.3 * henyey_greenstein(0.0, 0.9) * 2.0 * profile[bin] *
                            (std::exp(-sigma_t * u0) - std::exp(-sigma_t * (u0 + texel))) / sigma_t;
            }
            // Both integrate the same texel averages along the ray, each texel's exponential
            // exactly. The beams' texels differ from the histogram's by the flat triangles' chord
            // error, (k h)^2 / 8 = 7.5e-5 for cells of h = 1/256 wavelength, and the histogram's
            // by its discreteness, a sample or two of the 65536 per texel at each texel edge
            // (3e-5): about 1e-4 together; 5e-4 allowed (measured 2.5e-5 to 3.7e-5). The flat
            // in-scatter differs by 40% to 100% here.
            EXPECT_NEAR(got[c], expected, 5e-4 * expected) << "channel " << c;
        }
    }
}

}  // namespace
}  // namespace vkw::ref
