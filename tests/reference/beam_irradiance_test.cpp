// The reference's sun irradiance at receiver points under wavy water (tools/reference/
// beam_irradiance.hpp): a flat surface's beams give the closed form on planes of any tilt;
// under a sine, the floor's irradiance averaged over many points equals the beam-mapped
// floor map's average (an independent way to spread the same flux); a visibility test that
// blocks everything leaves nothing; and a scene with meshes under the waves renders.
#include "tools/reference/beam_irradiance.hpp"
#include "engine/scene/scene_loader.hpp"
#include "engine/water/surface.hpp"
#include "tests/reference/sine_scene.hpp"
#include "tools/reference/floor_caustics.hpp"
#include "tools/reference/optics.hpp"
#include "tools/reference/reference_renderer.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <string>

namespace vkw::ref {
namespace {

constexpr double kIor = 1.333;

Scene sine_scene(double amplitude, double sun_elevation_deg) {
    return sine_scene_with_amplitude(amplitude, sun_elevation_deg);
}

const BeamIrradiance::Visibility kEverythingVisible = [](const glm::dvec3&, const glm::dvec3&, double,
                                                         const glm::dvec3&) { return true; };

TEST(reference_beam_irradiance, FlatSurfaceGivesTheClosedFormOnTiltedPlanes) {
    const Scene scene = sine_scene(0.0, 50.0);
    const auto surface = make_surface(scene.water->waves, 0.0, 0.0);
    const BeamIrradiance beams(scene, *surface, 64, 0.0);  // at the points
    const glm::dvec3 s = scene.sun.direction;
    const glm::dvec3 t = *refract(s, {0.0, 1.0, 0.0}, 1.0 / kIor);
    const double cos_s = -s.y, cos_t = -t.y;
    const double e_perp0 = 2.0 * cos_s * (1.0 - fresnel_reflectance(cos_s, 1.0, kIor)) / cos_t;
    // Points off the grid's lines (generic offsets), normals from flat to steep, all lit.
    const glm::dvec3 points[] = {{0.0137, -0.61, 0.2291}, {-0.3311, -0.27, -0.1719}, {0.2753, -0.853, 0.0417}};
    const glm::dvec3 normals[] = {
        {0.0, 1.0, 0.0}, glm::normalize(glm::dvec3(0.6, 1.0, 0.2)), glm::normalize(glm::dvec3(-1.0, 0.3, 0.4))};
    for (const glm::dvec3& p : points) {
        for (glm::dvec3 n : normals) {
            if (glm::dot(t, n) > 0.0) n = -n;  // the lit side
            const double cos_receiver = -glm::dot(t, n);
            ASSERT_GT(cos_receiver, 0.0);
            const glm::dvec3 e = beams.irradiance(p, n, kEverythingVisible);
            for (int c = 0; c < 3; ++c) {
                const double expected = e_perp0 * cos_receiver * std::exp(-scene.medium.sigma_t()[c] * (-p.y / cos_t));
                // Congruent beams: each footprint is the surface triangle's parallel projection,
                // flux / area is exact up to a few dozen double roundings.
                EXPECT_NEAR(e[c], expected, 1e-9 * expected)
                    << "point " << p.x << " normal " << n.x << " channel " << c;
            }
        }
    }
}

TEST(reference_beam_irradiance, NothingReachesThroughABlockedBeam) {
    const Scene scene = sine_scene(0.02, 50.0);
    const auto surface = make_surface(scene.water->waves, 0.0, 0.0);
    const BeamIrradiance beams(scene, *surface, 128, 0.01);
    const auto blocked = [](const glm::dvec3&, const glm::dvec3&, double, const glm::dvec3&) { return false; };
    EXPECT_EQ(beams.irradiance({0.1, -1.0, 0.2}, {0.0, 1.0, 0.0}, blocked), glm::dvec3(0.0));
}

TEST(reference_beam_irradiance, FloorAverageUnderASineEqualsTheBeamMappedFloorMap) {
    // The sun overhead over a sine of slope 0.25 (amplitude 0.02 m, wavelength 0.5 m), floor 1 m
    // down: focal curves cross the floor. Averaged over x in [-0.5, 0.5] (two wavelengths, so
    // the average is the flux per area whatever the pattern), the point irradiance of the beams
    // and the floor map's texel-averaged irradiance spread the same beams' flux.
    const Scene scene = sine_scene(0.02, 90.0);
    const auto surface = make_surface(scene.water->waves, 0.0, 0.0);
    const BeamIrradiance beams(scene, *surface, 512, 0.0);  // at the points
    const FloorCausticMap map(scene, *surface, 2048, 512);
    const int samples = 4000;
    glm::dvec3 beam_mean(0.0), map_mean(0.0);
    for (int i = 0; i < samples; ++i) {
        const double x = -0.5 + (i + 0.5) / samples;  // 0.25 mm apart
        beam_mean += beams.irradiance({x, -1.0, 0.0123}, {0.0, 1.0, 0.0}, kEverythingVisible) / double(samples);
        map_mean += map.irradiance(x, 0.0123) / double(samples);
    }
    for (int c = 0; c < 3; ++c) {
        // The point irradiance near a focal curve grows as 1/sqrt(distance): its sample mean
        // at pitch p misses O(sqrt(p / lambda)) of the spike's integral, about
        // sqrt(2.5e-4 / 0.5) = 2.2% of the folds' share at most; the map's texels (4 mm)
        // average exactly. The folds carry well under half the flux: 1% bounds the difference
        // (measured: 0.05%).
        std::printf("[ figures  ] channel %d: beams %.6f, floor map %.6f\n", c, beam_mean[c], map_mean[c]);
        EXPECT_NEAR(beam_mean[c], map_mean[c], 0.01 * map_mean[c]) << "channel " << c;
    }
}

TEST(reference_beam_irradiance, AParallelogramPatchAveragesAsTheFloorMapsTexels) {
    // The beams and the floor map cut the same surface into the same triangles and spread each
    // footprint's flux by exact overlap, so a patch that is one texel holds that texel's value,
    // and a patch of two texels side by side (its edges given in either order, along z first)
    // their mean, to the clipping's rounding.
    const Scene scene = sine_scene(0.02, 60.0);
    const auto surface = make_surface(scene.water->waves, 0.0, 0.0);
    const FloorCausticMap map(scene, *surface, 256, 256);
    const BeamIrradiance beams(scene, *surface, 256, 0.0);
    const double texel = 8.0 / 256;  // the floor is 8 m wide
    double lit = 0.0;
    for (int i = 100; i < 156; i += 3) {
        const double x = -4.0 + (i + 0.5) * texel, z = -4.0 + (130 + 0.5) * texel;
        const glm::dvec3 one = beams.irradiance({x, -1.0, z}, {0.0, 1.0, 0.0}, kEverythingVisible,
                                                BeamIrradiance::Patch{{texel, 0.0, 0.0}, {0.0, 0.0, texel}});
        const glm::dvec3 two = beams.irradiance({x, -1.0, z + 0.5 * texel}, {0.0, 1.0, 0.0}, kEverythingVisible,
                                                BeamIrradiance::Patch{{0.0, 0.0, 2.0 * texel}, {texel, 0.0, 0.0}});
        const glm::dvec3 expected_two = 0.5 * (map.irradiance(x, z) + map.irradiance(x, z + texel));
        for (int c = 0; c < 3; ++c) {
            EXPECT_NEAR(one[c], map.irradiance(x, z)[c], 1e-9 * (1.0 + one[c])) << "x " << x;
            EXPECT_NEAR(two[c], expected_two[c], 1e-9 * (1.0 + two[c])) << "x " << x;
        }
        lit = std::max(lit, one.x);
    }
    EXPECT_GT(lit, 1.0);
}

TEST(reference_beam_irradiance, MeshesUnderTheWavesRender) {
    // A box under the waves (refused before) renders finite and non-negative, its shadow
    // leaving the floor under it darker than the open floor.
    const Scene scene = parse_scene(R"({
      "camera": {"position": [0, 3, 0.001], "target": [0, -1, 0], "fov_y_deg": 50},
      "sun": {"elevation_deg": 90, "irradiance": [2, 2, 2]},
      "sky": {"radiance": [0.1, 0.1, 0.1]},
      "floor": {"height": -1, "half_extent": 4},
      "water": {"level": 0, "half_extent": 2,
                "waves": {"model": "sum", "components": [{"amplitude": 0.01, "wavelength": 0.5, "direction_deg": 0}]}},
      "receivers": [{"type": "box", "half_size": [0.3, 0.1, 0.3], "translation": [0, -0.5, 0]}]
    })",
                                    "box_under_waves.json");
    ReferenceReport report;
    const ImageRGBA32F image = render_reference(scene, {48, 48, 0, {}, {}}, &report);
    for (float v : image.rgba) {
        ASSERT_TRUE(std::isfinite(v));
        ASSERT_GE(v, 0.0f);
    }
    EXPECT_GT(report.caustic_refinement_change, 0.0);
    const ExtraLayer& caustic = image.layers.at(0);
    ASSERT_EQ(caustic.name, "caustic");
    // The box top (seen at the centre) is lit through the waves; the floor beside it too.
    EXPECT_GT(caustic.rgb[3 * (24 * 48 + 24)], 0.5f);
}

}  // namespace
}  // namespace vkw::ref
