// The godray passes in the frame: culled (sigma_s = 0), they are absent from the compiled graph
// and the image equals the one with the effect forced on; run twice, the lines give bit-identical
// images (64-bit fixed-point accumulation); and the two methods both declare their passes.
#include "engine/scene/scene_loader.hpp"
#include "passes/frame/frame_needs.hpp"
#include "passes/frame/renderer.hpp"
#include "tests/support/gpu_test.hpp"

#include <filesystem>
#include <string>
#include <vector>

namespace vkw::test {
namespace {

constexpr uint32_t kWidth = 48;
constexpr uint32_t kHeight = 32;

// The pool (waves, caustics) on a coarse grid, seen from under the water and above it.
Scene pool(std::vector<std::string> overrides) {
    overrides.insert(overrides.begin(), {"water.grid_resolution=64", "effects.godrays.grid=32"});
    return load_scene(std::filesystem::path(VKWATER_SOURCE_DIR) / "scenes/pool.json", overrides);
}

const std::vector<std::string> kNoScattering = {"medium.preset=null", "medium.sigma_a=[0.4, 0.1, 0.05]",
                                                "medium.sigma_s=[0, 0, 0]"};

std::vector<std::string> pass_names(const Scene& scene) {
    fg::FrameGraph graph(decide_frame_needs(scene, double(kWidth) / kHeight));
    FrameConstants constants = make_frame_constants(scene, kWidth, kHeight);
    build_frame_graph(graph, scene, &constants, kWidth, kHeight, VK_NULL_HANDLE, nullptr, nullptr);
    graph.compile(kWidth, kHeight);
    std::vector<std::string> names;
    for (const uint32_t pass : graph.compiled().order) names.push_back(graph.passes()[pass].name);
    return names;
}

size_t godray_passes(const std::vector<std::string>& names) {
    size_t count = 0;
    for (const std::string& name : names) count += name.rfind("godray", 0) == 0 ? 1 : 0;
    return count;
}

TEST(godrays_graph, WithoutScatteringThePassesAreAbsent) {
    EXPECT_EQ(godray_passes(pass_names(pool(kNoScattering))), 0u);
    std::vector<std::string> forced = kNoScattering;
    forced.push_back("effects.godrays.mode=on");
    // beams, depth, clear, lines, resolve, blur x, blur y, composite
    EXPECT_EQ(godray_passes(pass_names(pool(forced))), 8u);
    forced.push_back("effects.godrays.method=marched");
    EXPECT_EQ(godray_passes(pass_names(pool(forced))), 3u);  // depth, march, composite
}

using godrays_frame = GpuTest;

TEST_F(godrays_frame, CulledImageEqualsForcedOnImage) {
    // sigma_s = 0: every deposit is a product with sigma_s, so the counters stay 0, the resolve writes
    // 0 and the composite adds +0.0; the shading's analytic in-scatter, switched off when the godrays
    // run, is sigma_s times its integral and 0 either way. The same arithmetic on the same zeros: the
    // images are equal exactly, from under the water and from above it.
    for (const char* camera : {"camera.position=[0, -0.7, 3]", "camera.position=[0, 1.2, 4]"}) {
        std::vector<std::string> culled = kNoScattering;
        culled.push_back(camera);
        std::vector<std::string> forced = culled;
        forced.push_back("effects.godrays.mode=on");
        Renderer renderer(context());
        const RenderResult without = renderer.render(pool(culled), {kWidth, kHeight, true, fg::TimingMode::None});
        const size_t pipelines = renderer.pipelines().size();
        const RenderResult with = renderer.render(pool(forced), {kWidth, kHeight, true, fg::TimingMode::None});
        EXPECT_GT(renderer.pipelines().size(), pipelines) << "forcing the godrays on created no pipeline";
        EXPECT_EQ(without.image.rgba, with.image.rgba) << camera;
    }
}

TEST_F(godrays_frame, LinesAreBitIdenticalRunToRun) {
    const Scene scene = pool({"medium.preset=coastal", "camera.position=[0, -0.7, 3]"});
    Renderer first(context()), second(context());
    const RenderResult a = first.render(scene, {kWidth, kHeight, true, fg::TimingMode::None});
    const RenderResult b = second.render(scene, {kWidth, kHeight, true, fg::TimingMode::None});
    EXPECT_EQ(a.image.rgba, b.image.rgba);
}

}  // namespace
}  // namespace vkw::test
