// Guardado & Sánchez-Crespo 2004's procedural caustic, the baseline (effects.caustics.method = procedural,
// passes/caustics/caustics_procedural.hpp): under flat water its backward ray returns along the sun, so it
// is the flat-surface stand-in; under waves it stays finite and non-negative for every sun.
#include "engine/scene/scene_loader.hpp"
#include "passes/frame/renderer.hpp"
#include "tests/support/gpu_test.hpp"
#include "tools/metrics/metrics.hpp"

#include <cmath>
#include <filesystem>
#include <string>

namespace vkw::test {
namespace {

constexpr uint32_t kWidth = 64;
constexpr uint32_t kHeight = 48;

Scene builtin(const char* name, const std::vector<std::string>& overrides) {
    return load_scene(std::filesystem::path(VKWATER_SOURCE_DIR) / "scenes" / name, overrides);
}

using caustic_procedural = GpuTest;

TEST_F(caustic_procedural, FlatWaterGivesTheStandIn) {
    // calm with its caustic passes forced to run: the procedural map against the stand-in.
    Renderer renderer(context());
    const RenderOptions options{kWidth, kHeight, true, fg::TimingMode::None};
    const RenderResult stand_in = renderer.render(builtin("calm.json", {}), options);
    const RenderResult procedural = renderer.render(
        builtin("calm.json", {"effects.caustics.analytic_flat=false", "effects.caustics.method=procedural"}), options);
    // Flat water: the refracted ray is -s to fp32 rounding, its angle to the sun about 1e-4 rad
    // (acos near 1 of a dot product rounded to 2^-24: sqrt(2 x 6e-8)), which the 4 degree lobe turns
    // into exp(-(1e-4 / 0.07)^2) = 1 - 2e-6; the stand-in's own chain adds 1e-5 (the fp32 bound of
    // water_vs_reference_test.cpp): relMSE below (1.2e-5)^2 = 1.4e-10.
    const double rel_mse = metrics::rel_mse(metrics::rgb_view(procedural.image), metrics::rgb_view(stand_in.image),
                                            metrics::counted_pixels(kWidth, kHeight, nullptr));
    EXPECT_LT(rel_mse, 1.4e-10);
}

TEST_F(caustic_procedural, FiniteAndNonNegativeForEverySun) {
    // pool's waves (A k up to 0.3) under suns from grazing to overhead; the check mode scans every
    // target, the procedural map included, for NaN/Inf after its pass.
    Renderer renderer(context());
    for (const double elevation : {0.5, 5.0, 30.0, 60.0, 89.9, 90.0}) {
        SCOPED_TRACE(elevation);
        const RenderResult result = renderer.render(
            builtin("pool.json", {"effects.caustics.method=procedural", "effects.godrays.mode=off",
                                  "water.grid_resolution=128", "sun.elevation_deg=" + std::to_string(elevation)}),
            {kWidth, kHeight, true, fg::TimingMode::None});
        float lowest = 0.0f;
        for (const float v : result.image.rgba) {
            ASSERT_TRUE(std::isfinite(v));
            lowest = std::min(lowest, v);
        }
        EXPECT_GE(lowest, 0.0f);
    }
}

}  // namespace
}  // namespace vkw::test
