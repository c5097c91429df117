// The water's medium at the edges: extinction from 1e-6 to 1e3 per metre, water 1 km
// deep, and the images' continuity in sigma_t and in the phase function's g.
#include "tests/extreme/extreme_support.hpp"
#include "tests/support/gpu_test.hpp"

namespace vkw::test {
namespace {

// sigma_a = sigma_s = sigma_t / 2 in every channel (half the extinction scatters), g = 0.9.
std::string medium_with_sigma_t(double sigma_t) {
    char text[320];
    std::snprintf(text, sizeof text,
                  R"(medium={"sigma_a": [%.17g, %.17g, %.17g], "sigma_s": [%.17g, %.17g, %.17g], "g": 0.9})",
                  sigma_t / 2, sigma_t / 2, sigma_t / 2, sigma_t / 2, sigma_t / 2, sigma_t / 2);
    return text;
}

class extreme_sigma_t : public GpuTest, public ::testing::WithParamInterface<double> {};

TEST_P(extreme_sigma_t, FlatWaterStableAndEqualToTheClosedForm) {
    const std::string what = "sigma_t " + std::to_string(GetParam()) + " /m, flat water";
    Renderer renderer(context());
    expect_closed_form(expect_stable(context(), renderer, extreme_scene({medium_with_sigma_t(GetParam())}), what),
                       what);
}

TEST_P(extreme_sigma_t, WavyWaterStable) {
    Renderer renderer(context());
    expect_stable(context(), renderer, extreme_scene({medium_with_sigma_t(GetParam()), sine_waves(0.3)}),
                  "sigma_t " + std::to_string(GetParam()) + " /m, sine of slope 0.3");
}

INSTANTIATE_TEST_SUITE_P(PerMetre, extreme_sigma_t, ::testing::Values(1e-6, 1e-3, 1.0, 10.0, 100.0, 1e3),
                         [](const auto& param_info) {
                             char name[32];
                             std::snprintf(name, sizeof name, "%g", param_info.param);
                             std::string text = std::string("sigma_t_") + name;
                             for (char& ch : text) ch = (ch == '.' || ch == '-' || ch == '+') ? '_' : ch;
                             return text;
                         });

using extreme_deep_water = GpuTest;

TEST_F(extreme_deep_water, OneKilometreDeepStableAndEqualToTheClosedForm) {
    // The floor 1 km down and 2 km wide, the far plane beyond it: clear-ocean extinction gives
    // optical depths of 1197, 99 and 54 to the floor (fp32's normal range ends near 87: the red
    // and green floor light underflows to 0, which both renderers must reach without a NaN).
    const std::vector<std::string> deep = {"floor.height=-1000", "floor.half_extent=2000", "camera.far=5000"};
    Renderer renderer(context());
    expect_closed_form(expect_stable(context(), renderer, extreme_scene(deep), "1 km deep, flat water"),
                       "1 km deep, flat water");
    expect_stable(context(), renderer, extreme_scene(joined(deep, {sine_waves(0.3)})), "1 km deep, sine of slope 0.3");
}

using extreme_medium_continuity = GpuTest;

// As in extreme_sun_test.cpp: flat water, RMS_rt <= RMS_ref + 2e-5, factor 1.05.
constexpr double kFlatWaterFactor = 1.05;

TEST_F(extreme_medium_continuity, ImagesMoveSmoothlyWithSigmaT) {
    // p = sigma_t = 0.5 /m in every channel, delta = 0.1 /m.
    Renderer renderer(context());
    auto scene = [](double sigma_t) { return extreme_scene({medium_with_sigma_t(sigma_t)}); };
    expect_continuous("sigma_t (1/m)", renderer, scene, 0.5, 0.1, kFlatWaterFactor);
}

TEST_F(extreme_medium_continuity, ImagesMoveSmoothlyWithG) {
    // Turbid water (sigma_s = 0.7 to 0.96 /m) makes the in-scatter, the only term g moves, a good
    // part of the image: p = g = 0.5, delta = 0.1.
    auto scene = [](double g) {
        return extreme_scene({"medium={\"sigma_a\": [1.169, 0.0638, 0.015], \"sigma_s\": [0.71, 0.82, 0.96], \"g\": " +
                              std::to_string(g) + "}"});
    };
    Renderer renderer(context());
    expect_continuous("Henyey-Greenstein g", renderer, scene, 0.5, 0.1, kFlatWaterFactor);
}

}  // namespace
}  // namespace vkw::test
