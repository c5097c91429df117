// The photon pass's culling (passes/caustics/caustics_read_region.hpp) leaves the image unchanged
// bit for bit: RGB and the caustic layer, culling on against effects.caustics.cull = false, for the
// built-in scenes with caustics and cameras that stress the bound (close to the surface looking
// across it, steeply down from a corner). Where the bound does not exist (the camera may be under
// the water: ocean, underwater) culling is off, and the images are equal trivially; the cases stay
// so that a bound added there is tested at once. With culling the flux and the resolved map hold only
// the read texels' rectangle (CausticMapFrame::held), so these cases also test that nothing reads
// outside it (the map's other texels are undefined). That the region does leave texels out, and holds
// what the view reads, is tested on the CPU (tests/caustics/caustics_read_region_test.cpp).
#include "engine/scene/scene_loader.hpp"
#include "passes/frame/renderer.hpp"
#include "tests/support/gpu_test.hpp"

#include <filesystem>
#include <string>
#include <vector>

namespace vkw::test {
namespace {

constexpr uint32_t kWidth = 64, kHeight = 48;  // small: the photon pass runs at each scene's full grid

struct CullingCase {
    const char* name;
    const char* scene;
    std::vector<std::string> overrides;
};

class CausticCulling : public GpuTest, public ::testing::WithParamInterface<CullingCase> {};

TEST_P(CausticCulling, LeavesTheImageAndTheCausticLayerBitIdentical) {
    std::vector<std::string> kept = GetParam().overrides;
    kept.push_back("effects.caustics.cull=false");
    const auto path = std::filesystem::path(VKWATER_SOURCE_DIR) / "scenes" / GetParam().scene;
    RenderOptions options{kWidth, kHeight, true, fg::TimingMode::None};
    options.caustic_layer = true;
    Renderer renderer(context());
    const RenderResult culled = renderer.render(load_scene(path, GetParam().overrides), options);
    const RenderResult all = renderer.render(load_scene(path, kept), options);
    EXPECT_EQ(culled.image.rgba, all.image.rgba);
    ASSERT_EQ(culled.image.layers.size(), all.image.layers.size());
    for (size_t i = 0; i < culled.image.layers.size(); ++i) {
        EXPECT_EQ(culled.image.layers[i].name, all.image.layers[i].name);
        EXPECT_EQ(culled.image.layers[i].rgb, all.image.layers[i].rgb) << culled.image.layers[i].name;
    }
}

INSTANTIATE_TEST_SUITE_P(
    Scenes, CausticCulling,
    ::testing::Values(CullingCase{"pool", "pool.json", {}}, CullingCase{"lake", "lake.json", {}},
                      // The FFT ocean at a coarser grid: culling is off there, so only the cost changes.
                      CullingCase{"ocean", "ocean.json", {"water.grid_resolution=256"}},
                      CullingCase{"underwater", "underwater.json", {}},
                      CullingCase{"pool_oblique_near_the_surface",
                                  "pool.json",
                                  {"camera.position=[3, 0.12, 6]", "camera.target=[-2, 0.02, -8]"}},
                      CullingCase{"pool_steep_from_a_corner",
                                  "pool.json",
                                  {"camera.position=[9, 4, 9]", "camera.target=[2, -1.5, 2]"}},
                      // The blur reads around each texel, so the map stays whole while the photons are culled.
                      CullingCase{"pool_blurred", "pool.json", {"effects.caustic_blur.radius=2"}}),
    [](const auto& param_info) { return std::string(param_info.param.name); });

}  // namespace
}  // namespace vkw::test
