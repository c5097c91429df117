// What `vkwater bench` measures about a frame besides its error, on lavapipe with validation:
// the frame's memory (the transient heap plus each imported resource once) grows with the
// water grid, and every frame of a setting renders the scene at its water.time (the renderer
// keeps no clock), so the timed frames and the measured one are the same picture.
#include <gtest/gtest.h>

#include "engine/scene/scene_loader.hpp"
#include "passes/frame/renderer.hpp"
#include "passes/receivers/receiver_meshes.hpp"
#include "passes/water/water_surface.hpp"
#include "tests/support/gpu_test.hpp"
#include "tools/benchmarks/frame_memory.hpp"

#include <string>

namespace vkw::test {
namespace {

const std::string kScenes = std::string(VKWATER_SOURCE_DIR) + "/scenes/";
constexpr uint32_t kWidth = 64, kHeight = 48;

// The readback the renderer imports: RGBA32F.
constexpr uint64_t kReadbackBytes = uint64_t{kWidth} * kHeight * 4 * sizeof(float);

// Named like the other suites here, so that `ctest -R metrics` selects it.
class metrics_bench_frame : public GpuTest {
protected:
    bench::FrameMemory memory_of(const Scene& scene) {
        Renderer renderer(context());
        return bench::measure_frame_memory(renderer, scene, options_);
    }
    RenderOptions options_{kWidth, kHeight, false, fg::TimingMode::None};
};

TEST_F(metrics_bench_frame, MemoryGrowsWithTheWaterGrid) {
    // calm: no receiver meshes, no FFT ocean, so the readback is the frame's only import.
    uint64_t previous = 0;
    for (const uint32_t grid : {32u, 128u, 512u}) {
        // calm draws its water from the grid itself (nothing else reads the grid in calm).
        const Scene scene = load_scene(kScenes + "calm.json", {"water.grid_resolution=" + std::to_string(grid),
                                                               "water.mesh_resolution=" + std::to_string(grid)});
        const bench::FrameMemory memory = memory_of(scene);
        EXPECT_EQ(memory.imported_bytes, kReadbackBytes) << "grid " << grid;
        // The surface's vertex buffer is one transient of the heap, which holds every transient
        // whole (aliasing shares memory between resources, never splits one).
        EXPECT_GE(memory.transient_bytes, passes::water_surface_bytes(grid)) << "grid " << grid;
        EXPECT_GT(memory.total(), previous) << "grid " << grid;
        previous = memory.total();
    }
}

TEST_F(metrics_bench_frame, ImportedMeshesCountOnce) {
    // The lake's receiver meshes are imported by each pass that draws them (shadow map, scene
    // views, receivers); they occupy one vertex and one index buffer.
    const Scene scene = load_scene(kScenes + "lake.json", {"water.grid_resolution=16"});
    const passes::ReceiverMeshes meshes(context(), scene.receivers);
    fg::FrameGraph sizes;
    const uint32_t vertices = meshes.import_vertices(sizes).index, indices = meshes.import_indices(sizes).index;
    const uint64_t mesh_bytes =
        sizes.resources()[vertices].imported_buffer.size + sizes.resources()[indices].imported_buffer.size;
    EXPECT_EQ(memory_of(scene).imported_bytes, kReadbackBytes + mesh_bytes);
}

TEST_F(metrics_bench_frame, EveryFrameRendersTheSceneAtItsWaterTime) {
    const Scene scene = load_scene(kScenes + "pool.json", {"water.grid_resolution=32"});
    Renderer renderer(context());
    const ImageRGBA32F first = renderer.render(scene, options_).image;
    for (int frame = 0; frame < 2; ++frame) {
        EXPECT_EQ(renderer.render(scene, options_).image.rgba, first.rgba) << "frame " << frame + 2;
    }
    // Time does reach the picture: a clock advancing between frames would show.
    const Scene later = load_scene(kScenes + "pool.json", {"water.grid_resolution=32", "water.time=0.25"});
    EXPECT_NE(renderer.render(later, options_).image.rgba, first.rgba);
}

}  // namespace
}  // namespace vkw::test
