// The sun at the edges: grazing at 85, 89, 89.9 degrees from the zenith, on the
// horizon (90) and below it (91), exactly overhead and 1e-7 rad away from it; over flat water
// (where both renderers are closed form and must agree to fp32 rounding) and over a sine of slope
// 0.3 (caustics). And the images' continuity in the sun's angle.
#include "tests/extreme/extreme_support.hpp"
#include "tests/support/gpu_test.hpp"

#include <numbers>

namespace vkw::test {
namespace {

constexpr double kOneE7RadInDeg = 1e-7 * 180.0 / std::numbers::pi;

class extreme_sun : public GpuTest, public ::testing::WithParamInterface<double> {};

TEST_P(extreme_sun, FlatWaterStableAndEqualToTheClosedForm) {
    const double zenith = GetParam();
    const std::string what = "sun " + std::to_string(zenith) + " deg from the zenith, flat water";
    Renderer renderer(context());
    expect_closed_form(expect_stable(context(), renderer, extreme_scene({sun_at_zenith(zenith)}), what), what);
}

TEST_P(extreme_sun, WavyWaterStable) {
    const double zenith = GetParam();
    Renderer renderer(context());
    expect_stable(context(), renderer, extreme_scene({sun_at_zenith(zenith), sine_waves(0.3)}),
                  "sun " + std::to_string(zenith) + " deg from the zenith, sine of slope 0.3");
}

INSTANTIATE_TEST_SUITE_P(Zenith, extreme_sun, ::testing::Values(85.0, 89.0, 89.9, 90.0, 91.0, 0.0, kOneE7RadInDeg),
                         [](const auto& param_info) {
                             char name[32];
                             std::snprintf(name, sizeof name, "%.7f", param_info.param);
                             std::string text = std::string("deg_") + name;
                             for (char& ch : text) ch = ch == '.' ? '_' : ch;
                             return text;
                         });

using extreme_sun_continuity = GpuTest;

// Flat water: the reference is the closed form and the real-time image equals it to 1e-5 per
// value, so the two differences between neighbouring suns differ by at most 2e-5 relative per
// value: RMS_rt(delta) <= RMS_ref(delta) + 2e-5, i.e. factor 1 + 2e-5 / RMS_ref, below 1.01 for
// the RMS of 5e-3 and more measured here; 1.05 leaves room for the relMSE's dropping of its worst
// 0.1% of values, which may pick different values in the two images.
constexpr double kFlatWaterFactor = 1.05;

TEST_F(extreme_sun_continuity, ImagesMoveSmoothlyWithTheSunsAngle) {
    Renderer renderer(context());
    auto scene = [](double zenith) { return extreme_scene({sun_at_zenith(zenith)}); };
    for (const double p : {30.0, 85.0})
        expect_continuous("sun zenith angle (deg)", renderer, scene, p, 1.0, kFlatWaterFactor);
}

// Under a sine of slope 0.3 the floor's sunlight is the caustic map: the real-time one is the true
// caustic filtered by a normalised kernel (the photons' bilinear splat over texels of a cell's
// size), and a filter with unit L1 norm never amplifies a difference: ||K * (f(p + delta) - f(p))||
// <= ||f(p + delta) - f(p)||. So RMS_rt(delta) <= RMS_ref(delta) up to the relMSE's weights (each
// image is normalised by its own values, which the filtering lowers at the peaks) and the photon
// lattice's sampling: factor 1.25.
constexpr double kWavyWaterFactor = 1.25;

TEST_F(extreme_sun_continuity, CausticsMoveSmoothlyWithTheSunsAngle) {
    Renderer renderer(context());
    auto scene = [](double zenith) { return extreme_scene({sun_at_zenith(zenith), sine_waves(0.3)}); };
    for (const double p : {30.0, 85.0}) {
        expect_continuous("sun zenith angle (deg), sine of slope 0.3", renderer, scene, p, 1.0, kWavyWaterFactor);
    }
}

TEST_F(extreme_sun_continuity, OverheadAndOneTenMillionthOfARadianAwayAgree) {
    // Too small a step for the ratio test (the difference is fp32 rounding), so the bound alone:
    // RMS_rt <= RMS_ref + 2e-5 (above: 1e-5 per value and image).
    Renderer renderer(context());
    const Scene overhead = extreme_scene({sun_at_zenith(0.0)}), tilted = extreme_scene({sun_at_zenith(kOneE7RadInDeg)});
    const double rt = std::sqrt(rel_mse(render_real_time(renderer, tilted), render_real_time(renderer, overhead)));
    const double ref = std::sqrt(rel_mse(render_reference(tilted), render_reference(overhead)));
    std::printf("overhead vs 1e-7 rad: RMS real time %.3e, reference %.3e\n", rt, ref);
    EXPECT_LE(rt, ref + 2e-5);
}

}  // namespace
}  // namespace vkw::test
