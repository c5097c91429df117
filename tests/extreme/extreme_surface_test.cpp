// The water's surface at the edges: n = 1 (nothing refracts), total internal
// reflection seen from below, steep sines (slope 0.5, 1 and 2), folding Gerstner waves
// (steepness sum 1.5 with allow_folding), zero-area cells (a Gerstner cusp on a grid vertex),
// and the images' continuity in n.
#include "tests/extreme/extreme_support.hpp"
#include "tests/support/gpu_test.hpp"

namespace vkw::test {
namespace {

using extreme_surface = GpuTest;

TEST_F(extreme_surface, IndexOneStableAndEqualToTheClosedForm) {
    // The wide pool: unbent, the view rays reach the floor up to 3.5 m north of the origin.
    Renderer renderer(context());
    expect_closed_form(
        expect_stable(context(), renderer, extreme_scene(joined(kWidePool, {"water.ior=1"})), "n = 1, flat water"),
        "n = 1, flat water");
    expect_stable(context(), renderer, extreme_scene({"water.ior=1", sine_waves(0.3)}), "n = 1, sine of slope 0.3");
}

// The camera 0.5 m under the surface looking north and up 40 degrees, 60 degree field of view: the
// rays rise 10 to 70 degrees above the horizontal, so the top of the frame lies inside Snell's
// window (above 41.4 degrees) and the rest sees the total internal reflection of the floor.
const std::vector<std::string> kFromBelow = {"camera.position=[0, -0.5, 1]", "camera.target=null",
                                             "camera.direction=[0, 0.6428, -0.7660]"};

TEST_F(extreme_surface, TotalInternalReflectionFromBelowStableAndEqualToTheClosedForm) {
    Renderer renderer(context());
    // The wide pool: the reflected rays come down up to 6 m further north.
    expect_closed_form(
        expect_stable(context(), renderer, extreme_scene(joined(kWidePool, kFromBelow)), "TIR from below, flat water"),
        "TIR from below, flat water");
    expect_stable(context(), renderer, extreme_scene(joined(kFromBelow, {sine_waves(0.3)})),
                  "TIR from below, sine of slope 0.3");
}

class extreme_steep : public GpuTest, public ::testing::WithParamInterface<double> {};

TEST_P(extreme_steep, SineStable) {
    Renderer renderer(context());
    // Wavelength 0.5 m: slope 2 is A = 0.16 m, the floor (1 m down) stays under the troughs.
    expect_stable(context(), renderer, extreme_scene({sine_waves(GetParam())}),
                  "sine of slope " + std::to_string(GetParam()));
}

INSTANTIATE_TEST_SUITE_P(Slope, extreme_steep, ::testing::Values(0.5, 1.0, 2.0), [](const auto& param_info) {
    return "slope_" + std::to_string(int(param_info.param * 10)) + "_tenths";
});

TEST_F(extreme_surface, FoldingGerstnerWavesStable) {
    // Two Gerstner waves along x, steepness 0.75 each: the sum 1.5 folds the surface over itself
    // (only with allow_folding).
    Renderer renderer(context());
    expect_stable(context(), renderer,
                  extreme_scene({R"(water.waves={"model":"sum","allow_folding":true,"components":[)"
                                 R"({"amplitude":0.06,"wavelength":0.5,"steepness":0.75},)"
                                 R"({"amplitude":0.04,"wavelength":0.35,"steepness":0.75,"phase_deg":40}]})"}),
                  "folding Gerstner waves (steepness sum 1.5)", kFoldingQuality);
}

TEST_F(extreme_surface, ZeroAreaCellsAtAGerstnerCuspStable) {
    // Steepness 1 (the most a wave may have without folding) along x: at theta = 90 degrees the
    // horizontal map x0 + cos(theta) / k has zero derivative and dP/du = 0 exactly, the cells
    // either side of that vertex have their area go to 0, and the normal is undefined. Phase 90
    // puts the cusp on the grid vertex x0 = 0 (the 32-cell grid's middle column).
    Renderer renderer(context());
    expect_stable(
        context(), renderer,
        extreme_scene({R"(water.waves={"model":"sum","components":[)"
                       R"({"amplitude":0.0795774715459477,"wavelength":0.5,"steepness":1,"phase_deg":90}]})"}),
        "Gerstner cusp on a grid vertex (zero-area cells)", kFoldingQuality);
}

using extreme_surface_continuity = GpuTest;

// As in extreme_sun_test.cpp: flat water, RMS_rt <= RMS_ref + 2e-5, factor 1.05.
constexpr double kFlatWaterFactor = 1.05;

TEST_F(extreme_surface_continuity, ImagesMoveSmoothlyWithTheIndexOfRefraction) {
    Renderer renderer(context());
    auto scene = [](double n) { return extreme_scene({"water.ior=" + std::to_string(n)}); };
    expect_continuous("index of refraction", renderer, scene, 1.333, 0.02, kFlatWaterFactor);
}

}  // namespace
}  // namespace vkw::test
