// The camera-medium split (passes/water/camera_medium.hpp) against a CPU classification of the
// same pixels, and the underwater_view rule's culled image against its forced-on image.
//
// CPU rule: the near-plane point P of pixel (x, y)'s ray (through the pixel centre, as
// vkw::ref::camera_ray) is in the water iff |P.x|, |P.z| <= E, P.y > bottom and
// P.y < h(P.x, P.z) (make_surface(...)->height_at): a point exactly at the surface's height
// counts as above. The mask must agree at every pixel except those within one pixel of the
// boundary's trace on the near plane (the CPU class of one of the 8 neighbouring pixel
// centres differs): there fp32 geometry, the grid's chords (below a tenth of a pixel here)
// and the rasteriser's top-left rule may fall either way.
#include "engine/framegraph/pass_context.hpp"
#include "engine/scene/scene_loader.hpp"
#include "engine/water/surface.hpp"
#include "passes/frame/frame_needs.hpp"
#include "passes/frame/renderer.hpp"
#include "passes/present/readback.hpp"
#include "passes/water/camera_medium.hpp"
#include "tests/support/builtin_scene.hpp"
#include "tests/support/gpu_test.hpp"
#include "tools/reference/reference_renderer.hpp"

#include <cmath>
#include <cstring>
#include <filesystem>

namespace vkw::test {
namespace {

constexpr uint32_t kWidth = 64;
constexpr uint32_t kHeight = 47;  // odd: the middle row's centres lie on the camera's horizontal plane

// The split's mask for `scene` (underwater_view forced on), read back from the real frame graph.
std::vector<uint8_t> render_mask(Context& context, fg::PipelineStore& pipelines, const Scene& scene) {
    fg::FrameNeeds needs = decide_frame_needs(scene, double(kWidth) / double(kHeight));
    const FrameConstants constants = make_frame_constants(scene, kWidth, kHeight);
    Buffer hdr(context, {VkDeviceSize{kWidth} * kHeight * 16, VK_BUFFER_USAGE_TRANSFER_DST_BIT, true}, "HDR readback");
    Buffer mask(context, {VkDeviceSize{kWidth} * kHeight, VK_BUFFER_USAGE_TRANSFER_DST_BIT, true}, "mask readback");
    fg::FrameGraph graph(std::move(needs));
    build_frame_graph(graph, scene, &constants, kWidth, kHeight, hdr.handle(), nullptr, nullptr);
    passes::add_readback_pass(graph, graph.blackboard().get(keys::kCameraMedium), mask.handle(),
                              VkDeviceSize{kWidth} * kHeight, "mask readback");
    graph.compile(kWidth, kHeight);
    fg::FrameExecutor executor(context, graph, pipelines, {true, fg::TimingMode::None});
    executor.execute();
    std::vector<uint8_t> texels(size_t{kWidth} * kHeight);
    std::memcpy(texels.data(), mask.mapped(), texels.size());
    return texels;
}

std::vector<bool> cpu_classification(const Scene& scene) {
    const Water& water = *scene.water;
    const auto surface = make_surface(water.waves, water.level, water.time);
    const glm::dmat4 view = view_matrix(scene.camera);
    const glm::dvec3 forward = -glm::dvec3(view[0][2], view[1][2], view[2][2]);
    std::vector<bool> inside(size_t{kWidth} * kHeight);
    for (uint32_t y = 0; y < kHeight; ++y) {
        for (uint32_t x = 0; x < kWidth; ++x) {
            const ref::Ray ray = ref::camera_ray(scene.camera, kWidth, kHeight, x + 0.5, y + 0.5);
            const glm::dvec3 p =
                ray.origin + ray.direction * (scene.camera.near_plane / glm::dot(ray.direction, forward));
            inside[size_t{y} * kWidth + x] = std::abs(p.x) <= water.half_extent && std::abs(p.z) <= water.half_extent &&
                                             p.y > water_bottom(scene) && p.y < surface->height_at(p.x, p.z);
        }
    }
    return inside;
}

struct SplitCase {
    const char* name;
    double camera_height;
    bool wavy;
    double near_plane;
};

void PrintTo(const SplitCase& c, std::ostream* os) { *os << c.name; }

class StencilSplit : public GpuTest, public ::testing::WithParamInterface<SplitCase> {};

TEST_P(StencilSplit, MaskMatchesCpuClassification) {
    const SplitCase& c = GetParam();
    // Looking 15 degrees down over the water; the far plane (6 m) is well short of the walls
    // and the bottom (20 m away): crossings past it must still count.
    std::vector<std::string> overrides = {
        "camera.position=[0.3, " + std::to_string(c.camera_height) + ", 0.2]", "camera.direction=null",
        "camera.target=[0.3, " + std::to_string(c.camera_height - 0.26795) + ", -0.8]",
        "camera.near=" + std::to_string(c.near_plane), "camera.far=6", "effects.underwater_view.mode=on",
        // The GPU volume's surface is the grid's triangles, the CPU's the exact sines: their
        // chords sag by at most sum A k^2 dx^2 / 8 = 1.1e-4 m (dx = 10 m / 1024), a tenth of the
        // smallest pixel on a near plane here (1.2 mm at 5 cm), inside the one-pixel band.
        "water.half_extent=5", "water.grid_resolution=1024"};
    if (c.wavy) {
        overrides.push_back(R"(water.waves={"model": "sum", "components": [)"
                            R"({"amplitude": 0.3, "wavelength": 1.7, "direction_deg": 20},)"
                            R"({"amplitude": 0.15, "wavelength": 0.9, "direction_deg": 75, "phase_deg": 40}]})");
    }
    const Scene scene = builtin_scene("calm.json", overrides);
    ASSERT_DOUBLE_EQ(scene.camera.position.y, c.camera_height);
    fg::PipelineStore pipelines;
    const std::vector<uint8_t> mask = render_mask(context(), pipelines, scene);
    const std::vector<bool> cpu = cpu_classification(scene);

    size_t compared = 0, in_water = 0, mismatches = 0;
    for (uint32_t y = 0; y < kHeight; ++y) {
        for (uint32_t x = 0; x < kWidth; ++x) {
            const bool here = cpu[size_t{y} * kWidth + x];
            bool near_boundary = false;
            for (int dy = -1; dy <= 1; ++dy) {
                for (int dx = -1; dx <= 1; ++dx) {
                    const int nx = int(x) + dx, ny = int(y) + dy;
                    if (nx < 0 || ny < 0 || nx >= int(kWidth) || ny >= int(kHeight)) continue;
                    near_boundary = near_boundary || cpu[size_t(ny) * kWidth + size_t(nx)] != here;
                }
            }
            if (near_boundary) continue;
            ++compared;
            in_water += here;
            const bool gpu = mask[size_t{y} * kWidth + x] != 0;
            if (gpu != here && ++mismatches <= 5) {
                ADD_FAILURE() << c.name << ": pixel (" << x << ", " << y << ") GPU " << gpu << ", CPU " << here;
            }
        }
    }
    EXPECT_EQ(mismatches, 0u) << c.name;
    EXPECT_GT(compared, size_t{kWidth} * kHeight * 3 / 4) << c.name << ": most pixels must be away from the boundary";
    RecordProperty("pixels_in_water", static_cast<int>(in_water));
}

INSTANTIATE_TEST_SUITE_P(
    CameraHeights, StencilSplit,
    ::testing::Values(SplitCase{"flat_below_1m", -1.0, false, 0.05}, SplitCase{"flat_below_1um", -1e-6, false, 0.05},
                      SplitCase{"flat_at_0", 0.0, false, 0.05}, SplitCase{"flat_above_1um", 1e-6, false, 0.05},
                      SplitCase{"flat_above_1m", 1.0, false, 0.05}, SplitCase{"wavy_below_1m", -1.0, true, 0.05},
                      SplitCase{"wavy_below_1um", -1e-6, true, 0.05}, SplitCase{"wavy_at_0", 0.0, true, 0.05},
                      SplitCase{"wavy_above_1um", 1e-6, true, 0.05}, SplitCase{"wavy_above_1m", 1.0, true, 0.05},
                      // A 2 m near plane puts the wavy surface and the bottom (y = -2) across it.
                      SplitCase{"flat_below_1m_near_2m", -1.0, false, 2.0},
                      SplitCase{"wavy_at_0_near_2m", 0.0, true, 2.0},
                      SplitCase{"wavy_below_1m_near_2m", -1.0, true, 2.0},
                      SplitCase{"wavy_above_1m_near_2m", 1.0, true, 2.0}),
    [](const auto& param_info) { return std::string(param_info.param.name); });

using UnderwaterViewRule = GpuTest;

TEST_F(UnderwaterViewRule, CulledImageEqualsForcedOnImage) {
    // Camera 3 m above flat water: no ray starts in the water, the rule culls the camera-medium split and
    // the shading takes the per-frame medium; forced on, the all-air mask must give the
    // same image exactly.
    Renderer renderer(context());
    const RenderOptions options{kWidth, kHeight, true, fg::TimingMode::None};
    const RenderResult culled = renderer.render(builtin_scene("calm.json"), options);
    const size_t pipelines_culled = renderer.pipelines().size();
    ASSERT_FALSE(renderer.pipelines().contains("camera medium/camera medium/flat/dynamic"));
    const RenderResult forced_on =
        renderer.render(builtin_scene("calm.json", {"effects.underwater_view.mode=on"}), options);
    EXPECT_GT(renderer.pipelines().size(), pipelines_culled);
    EXPECT_TRUE(renderer.pipelines().contains("camera medium/camera medium/flat/dynamic"));
    EXPECT_EQ(culled.image.rgba, forced_on.image.rgba);
}

}  // namespace
}  // namespace vkw::test
