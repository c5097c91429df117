// The calibration pass: recorded in every timed frame and reported under its name, never culled
// (nothing reads its target), and it changes no pixel of the image; untimed frames leave it out.
#include "passes/common/calibration.hpp"
#include "engine/scene/scene_loader.hpp"
#include "passes/frame/renderer.hpp"
#include "tests/support/gpu_test.hpp"

#include <algorithm>
#include <filesystem>

namespace vkw::test {
namespace {

using Calibration = GpuTest;

bool reports_calibration(const fg::FrameReport& report) {
    return std::any_of(report.passes.begin(), report.passes.end(),
                       [](const fg::PassTime& pass) { return pass.pass == passes::kCalibrationPassName; });
}

TEST_F(Calibration, TimedFramesCarryItAndTheImageIsUnchanged) {
    const Scene scene = load_scene(std::filesystem::path(VKWATER_SOURCE_DIR) / "scenes/calm.json");
    Renderer untimed_renderer(context());
    const RenderResult untimed = untimed_renderer.render(scene, {64, 48, true, fg::TimingMode::None});
    EXPECT_FALSE(reports_calibration(untimed.timing));

    Renderer timed_renderer(context());
    const RenderResult timed = timed_renderer.render(scene, {64, 48, true, fg::TimingMode::Fences});
    ASSERT_TRUE(reports_calibration(timed.timing));
    for (const fg::PassTime& pass : timed.timing.passes) {
        if (pass.pass == passes::kCalibrationPassName) {
            EXPECT_GT(pass.ms, 0.0);
            EXPECT_EQ(pass.created_bytes, 64u * 48u * 16u) << "one RGBA32F target at the output size";
        }
    }
    EXPECT_EQ(timed.image.rgba, untimed.image.rgba);
}

}  // namespace
}  // namespace vkw::test
