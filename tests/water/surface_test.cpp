// The model-independent parts: make_surface's choice of model, the flat surface, and the
// normal's orientation and cusp fallback.
#include <cmath>

#include <gtest/gtest.h>

#include "engine/water/fft_ocean_surface.hpp"
#include "engine/water/flat_surface.hpp"
#include "engine/water/surface.hpp"
#include "engine/water/wave_sum_surface.hpp"
#include "tests/water/water_test_support.hpp"

namespace vkw {
namespace {

TEST(water_surface, FlatSurfaceIsThePlaneAtTheLevel) {
    const FlatSurface flat(0.25);
    const SurfacePoint p = flat.at_parameter(3.0, -4.0);
    EXPECT_EQ(p.position, glm::dvec3(3.0, 0.25, -4.0));
    EXPECT_EQ(p.normal, glm::dvec3(0.0, 1.0, 0.0));
    EXPECT_EQ(p.dP_du, glm::dvec3(1.0, 0.0, 0.0));
    EXPECT_EQ(p.dP_dv, glm::dvec3(0.0, 0.0, 1.0));
    EXPECT_TRUE(flat.is_heightfield());
    EXPECT_EQ(flat.max_amplitude(), 0.0);
    EXPECT_EQ(flat.height_at(-7.5, 2.0), 0.25);
    // P is linear: central differences are exact but for rounding of x0 +- h (|x0| <= 4).
    test::expect_derivatives_match_differences(flat, 3.0, -4.0, 1e-5,
                                               test::central_difference_tolerance(1e-5, 0.0, 4.0));
}

TEST(water_surface, MakeSurfacePicksTheModel) {
    WaveSettings settings;
    EXPECT_NE(dynamic_cast<FlatSurface*>(make_surface(settings, 0.0, 0.0).get()), nullptr);
    settings.model = WaveModel::Sum;
    settings.components.push_back(WaveComponent{0.1, 2.0});
    EXPECT_NE(dynamic_cast<WaveSumSurface*>(make_surface(settings, 0.0, 0.0).get()), nullptr);
    settings.model = WaveModel::FftOcean;
    settings.ocean.resolution = 16;
    EXPECT_NE(dynamic_cast<FftOceanSurface*>(make_surface(settings, 0.0, 0.0).get()), nullptr);
}

TEST(water_surface, NormalPointsUpAndFallsBackAtCusps) {
    // Tangents of an overturned patch: the cross product points down and is flipped.
    const SurfacePoint overturned =
        make_surface_point(glm::dvec3(0.0), glm::dvec3(-1.0, 0.0, 0.0), glm::dvec3(0.0, 0.0, 1.0));
    EXPECT_EQ(overturned.normal, glm::dvec3(0.0, 1.0, 0.0));
    // A Gerstner cusp: dP_du = 0. The normal would be NaN; the vertical limit is returned.
    const SurfacePoint cusp = make_surface_point(glm::dvec3(0.0), glm::dvec3(0.0), glm::dvec3(0.0, 0.0, 1.0));
    EXPECT_EQ(cusp.normal, glm::dvec3(0.0, 1.0, 0.0));
}

TEST(water_surface, GerstnerCrestAtSteepnessOneIsACuspWithAVerticalNormal) {
    WaveSettings settings;
    // Crest where theta = k x0 + phase = pi / 2: at x0 = 0 with phase 90 degrees.
    settings.components.push_back(WaveComponent{0.1, 2.0, 0.0, 90.0, 1.0});
    const WaveSumSurface surface(settings, 0.0, 0.0);
    const SurfacePoint crest = surface.at_parameter(0.0, 0.0);
    EXPECT_NEAR(glm::length(crest.dP_du), 0.0, 1e-15);
    EXPECT_EQ(crest.normal, glm::dvec3(0.0, 1.0, 0.0));
}

}  // namespace
}  // namespace vkw
