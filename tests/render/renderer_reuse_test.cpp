// The renderer compiles its frame graph once per configuration and reuses it: a new
// camera changes the image without a recompile (the constants are read at record
// time), a new output size recompiles, and no pipeline is ever created twice.
#include "engine/scene/scene_loader.hpp"
#include "passes/frame/renderer.hpp"
#include "tests/support/gpu_test.hpp"

#include <filesystem>

namespace vkw::test {
namespace {

using RendererReuse = GpuTest;

TEST_F(RendererReuse, CompilesOncePerConfigurationAndUpdatesConstants) {
    Scene scene = load_scene(std::filesystem::path(VKWATER_SOURCE_DIR) / "scenes/pool.json");
    Renderer renderer(context());
    const RenderOptions options{64, 48, true, fg::TimingMode::None};
    const RenderResult first = renderer.render(scene, options);
    const size_t pipelines_after_first = renderer.pipelines().size();

    scene.camera.target.y += 2.0;  // look up: more sky, less floor
    const RenderResult second = renderer.render(scene, options);
    EXPECT_EQ(renderer.compile_count(), 1u);
    EXPECT_EQ(renderer.pipelines().size(), pipelines_after_first);
    EXPECT_NE(first.image.rgba, second.image.rgba) << "the new camera did not reach the shaders";

    renderer.render(scene, {32, 24, true, fg::TimingMode::None});
    EXPECT_EQ(renderer.compile_count(), 2u);
    EXPECT_EQ(renderer.pipelines().size(), pipelines_after_first);
}

}  // namespace
}  // namespace vkw::test
