// A box-filtered frame traces the caustic photons once: its first sub-frame makes the light-space
// map for the cameras of all of them and keeps it, and the later sub-frames read the kept map
// (RenderOptions::caustic_map_carry, passes/frame/supersampled_frame.hpp). The image must be the
// one that k^2 independent sub-frames give, bit for bit: every texel a sub-frame reads holds the
// sum of every photon that reaches it either way (integer addition), and the mean is taken in the
// same order. Under validation, in both recording kinds.
#include "engine/scene/scene_loader.hpp"
#include "passes/frame/renderer.hpp"
#include "passes/frame/supersampled_frame.hpp"
#include "tests/support/gpu_test.hpp"

#include <algorithm>
#include <filesystem>

namespace vkw::test {
namespace {

constexpr uint32_t kWidth = 64;
constexpr uint32_t kHeight = 48;

// pool at a 256^2 grid (so a frame takes a fraction of a second): its photon culling is on (the
// camera is above the water), so the kept map holds only the texels the sub-frames read; with
// the marched godrays, which sample the map in a compute shader, and with the blur.
Scene pool(const std::vector<std::string>& more = {}) {
    std::vector<std::string> overrides = {"water.grid_resolution=256"};
    overrides.insert(overrides.end(), more.begin(), more.end());
    return load_scene(std::filesystem::path(VKWATER_SOURCE_DIR) / "scenes" / "pool.json", overrides);
}

// The box filter's mean of independent sub-frames, each making its own map, summed as
// render_filtered sums.
RenderResult independent_sub_frames(Renderer& renderer, const Scene& scene, const RenderOptions& options,
                                    const PixelFilter& filter) {
    RenderResult sum;
    for (uint32_t i = 0; i < filter.samples; ++i) {
        Scene shifted = scene;
        shifted.camera.image_shift_ndc =
            image_shift_for_pixel_offset(filter.stratum_centre(i), options.width, options.height);
        RenderResult sub = renderer.render(shifted, options);
        if (i == 0) {
            sum = std::move(sub);
            continue;
        }
        for (size_t k = 0; k < sum.image.rgba.size(); ++k) sum.image.rgba[k] += sub.image.rgba[k];
        for (size_t l = 0; l < sum.image.layers.size(); ++l) {
            for (size_t k = 0; k < sum.image.layers[l].rgb.size(); ++k) {
                sum.image.layers[l].rgb[k] += sub.image.layers[l].rgb[k];
            }
        }
    }
    const float scale = 1.0f / static_cast<float>(filter.samples);
    for (float& v : sum.image.rgba) v *= scale;
    for (ExtraLayer& layer : sum.image.layers) {
        for (float& v : layer.rgb) v *= scale;
    }
    return sum;
}

class SupersampledCaustics : public GpuTest, public ::testing::WithParamInterface<fg::RecordingKind> {};

TEST_P(SupersampledCaustics, OneMapServesEverySubFrameBitForBit) {
    const PixelFilter filter = pixel_filter_from_spp(4);
    RenderOptions options{kWidth, kHeight, true, fg::TimingMode::None, GetParam()};
    options.caustic_layer = true;
    for (const std::vector<std::string>& variant :
         {std::vector<std::string>{}, std::vector<std::string>{"effects.godrays.method=\"marched\""},
          std::vector<std::string>{"effects.caustic_blur.radius=2"}}) {
        const Scene scene = pool(variant);
        Renderer renderer(context());
        const RenderResult carried = render_filtered(renderer, scene, options, filter);
        const RenderResult independent = independent_sub_frames(renderer, scene, options, filter);
        ASSERT_EQ(carried.image.layers.size(), 1u);
        ASSERT_EQ(independent.image.layers.size(), 1u);
        EXPECT_EQ(carried.image.rgba, independent.image.rgba) << (variant.empty() ? "" : variant[0]);
        EXPECT_EQ(carried.image.layers[0].rgb, independent.image.layers[0].rgb) << (variant.empty() ? "" : variant[0]);
        // Not a black or flat image: the caustic layer varies across the floor.
        const auto [lo, hi] =
            std::minmax_element(carried.image.layers[0].rgb.begin(), carried.image.layers[0].rgb.end());
        EXPECT_GT(*hi, 1.5f * *lo + 1e-3f);
    }
}

INSTANTIATE_TEST_SUITE_P(Recording, SupersampledCaustics,
                         ::testing::Values(fg::RecordingKind::DynamicRendering, fg::RecordingKind::RenderPassObject),
                         [](const auto& param_info) {
                             return param_info.param == fg::RecordingKind::DynamicRendering ? "dynamic" : "renderpass";
                         });

// The later sub-frames leave out the passes that make the map; the first adds the copy that keeps
// it. (Per-pass fence timing lists the passes that ran.)
TEST_F(GpuTest, LaterSubFramesTraceNoPhotons) {
    const Scene scene = pool();
    Renderer renderer(context());
    RenderOptions options{kWidth, kHeight, false, fg::TimingMode::Fences};
    options.sub_frame_shifts = {{0.01, 0.0}, {-0.01, 0.0}};
    auto ran = [](const RenderResult& result, const std::string& pass) {
        return std::any_of(result.timing.passes.begin(), result.timing.passes.end(),
                           [&](const fg::PassTime& p) { return p.pass == pass; });
    };
    Scene shifted = scene;
    shifted.camera.image_shift_ndc = options.sub_frame_shifts[0];
    options.caustic_map_carry = CausticMapCarry::Keep;
    const RenderResult first = renderer.render(shifted, options);
    EXPECT_TRUE(ran(first, "caustic photons"));
    EXPECT_TRUE(ran(first, "keep caustic map"));
    shifted.camera.image_shift_ndc = options.sub_frame_shifts[1];
    options.caustic_map_carry = CausticMapCarry::Reuse;
    const RenderResult second = renderer.render(shifted, options);
    EXPECT_FALSE(ran(second, "caustic photons"));
    EXPECT_FALSE(ran(second, "caustic resolve"));
    EXPECT_FALSE(ran(second, "keep caustic map"));
    EXPECT_TRUE(ran(second, "water"));
}

}  // namespace
}  // namespace vkw::test
