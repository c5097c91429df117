// The real-time renderer against the CPU reference renderer (tools/reference), rendered
// side by side at 64x48, for the scenes where the real-time shading has no
// approximation left (flat water: the analytic lookups are exact): the error must be
// fp32 rounding alone. Plus the water rule's culled image against its forced-on image.
#include "engine/scene/scene_loader.hpp"
#include "passes/frame/renderer.hpp"
#include "passes/frame/supersampled_frame.hpp"
#include "tests/support/builtin_scene.hpp"
#include "tests/support/gpu_test.hpp"
#include "tools/metrics/metrics.hpp"
#include "tools/reference/reference_renderer.hpp"

#include <filesystem>
#include <string>
#include <utility>

namespace vkw::test {
namespace {

constexpr uint32_t kWidth = 64;
constexpr uint32_t kHeight = 48;

// Where the real-time shading has no approximation left (flat water), the real-time image against
// the reference's differs by fp32 rounding alone. The shader chain (frame constants rounded to fp32,
// Fresnel, refraction, exp and the in-scatter series) costs at most a few hundred fp32 roundings,
// i.e. a relative error per value below 1e-5 (its derivation: tests/optics bound each piece near
// 1e-6): relMSE <= (1e-5)^2 = 1e-10, and |bias| <= 1e-5.
void expect_fp32_rounding_apart(const ImageRGBA32F& real_time, const ImageRGBA32F& reference, const std::string& what) {
    const auto pixels = metrics::counted_pixels(kWidth, kHeight, nullptr);
    EXPECT_LT(metrics::rel_mse(metrics::rgb_view(real_time), metrics::rgb_view(reference), pixels), 1e-10) << what;
    EXPECT_LT(std::abs(metrics::mean_bias(metrics::rgb_view(real_time), metrics::rgb_view(reference), pixels)), 1e-5)
        << what;
}

// The real-time frame and the reference of `scene`, at kWidth x kHeight, point-sampled.
std::pair<ImageRGBA32F, ImageRGBA32F> both_renderers(Renderer& renderer, const Scene& scene) {
    return {renderer.render(scene, {kWidth, kHeight, true, fg::TimingMode::None}).image,
            ref::render_reference(scene, {kWidth, kHeight, 0, {}})};
}

class WaterAgainstReference : public GpuTest, public ::testing::WithParamInterface<const char*> {};

TEST_P(WaterAgainstReference, FlatWaterMatchesToFp32Rounding) {
    Renderer renderer(context());
    const auto [real_time, reference] = both_renderers(renderer, builtin_scene(GetParam()));
    expect_fp32_rounding_apart(real_time, reference, GetParam());
}

// A box-filtered frame (4 sub-frames) against the mean of four reference images whose cameras are
// shifted by the same strata's centres: the sub-frames must see exactly the rays the shifted
// projection gives, and their mean must be taken right. Each reference pixel traces its centre
// through the shifted camera, so the two sides sample the same four rays per pixel, and the bound
// is the point-sampled one above: a mean of four values each within 1e-5 relative.
TEST_P(WaterAgainstReference, SupersampledFrameSeesTheShiftedRays) {
    const Scene scene = builtin_scene(GetParam());
    const PixelFilter filter = pixel_filter_from_spp(4);
    Renderer renderer(context());
    const RenderResult real_time =
        render_filtered(renderer, scene, {kWidth, kHeight, true, fg::TimingMode::None}, filter);
    ImageRGBA32F mean;
    for (uint32_t i = 0; i < filter.samples; ++i) {
        Scene shifted = scene;
        shifted.camera.image_shift_ndc = image_shift_for_pixel_offset(filter.stratum_centre(i), kWidth, kHeight);
        const ImageRGBA32F sample = ref::render_reference(shifted, {kWidth, kHeight, 0, {}});
        if (i == 0) {
            mean = sample;
            for (float& v : mean.rgba) v = 0.0f;
        }
        for (size_t k = 0; k < mean.rgba.size(); ++k) mean.rgba[k] += sample.rgba[k] / float(filter.samples);
    }
    const auto pixels = metrics::counted_pixels(kWidth, kHeight, nullptr);
    const double rel_mse = metrics::rel_mse(metrics::rgb_view(real_time.image), metrics::rgb_view(mean), pixels);
    const double bias = metrics::mean_bias(metrics::rgb_view(real_time.image), metrics::rgb_view(mean), pixels);
    EXPECT_LT(rel_mse, 1e-10) << GetParam();
    EXPECT_LT(std::abs(bias), 1e-5) << GetParam();
    // And it is not the point-sampled image: the shift moved the rays.
    const RenderResult centres = renderer.render(scene, {kWidth, kHeight, true, fg::TimingMode::None});
    EXPECT_GT(metrics::rel_mse(metrics::rgb_view(centres.image), metrics::rgb_view(mean), pixels),
              1e3 * rel_mse + 1e-12)
        << GetParam();
}

// One sample per pixel is the plain frame, bit for bit.
TEST_P(WaterAgainstReference, OneSampleIsThePlainFrame) {
    const Scene scene = builtin_scene(GetParam());
    Renderer renderer(context());
    const RenderOptions options{kWidth, kHeight, true, fg::TimingMode::None};
    const RenderResult plain = renderer.render(scene, options);
    const RenderResult filtered = render_filtered(renderer, scene, options, pixel_filter_from_spp(1));
    EXPECT_EQ(plain.image.rgba, filtered.image.rgba) << GetParam();
}

INSTANTIATE_TEST_SUITE_P(Scenes, WaterAgainstReference, ::testing::Values("calm.json", "underwater.json"),
                         [](const auto& param_info) {
                             return std::string(param_info.param).substr(0, std::string(param_info.param).find('.'));
                         });

// A tiled floor (floor.tiles) seen through flat water, from above and from below: both renderers
// evaluate one pattern, the reference in double at each ray's hit and the real-time renderer in
// float per fragment, so every pixel agrees to the fp32 bound above but those whose hit lies
// within fp32 rounding of a grout line's edge (about 1e-6 m; at 64x48 a pixel's hit is that close
// to one of the 4 edges per tile side with a probability near 4e-6 / 0.25 = 2e-5, so 0.05 pixels
// are expected): at most one may take the other colour.
class TiledFloor : public GpuTest, public ::testing::WithParamInterface<const char*> {};

TEST_P(TiledFloor, MatchesTheReferenceToFp32Rounding) {
    // calm's camera, 3 m above the water looking 45 degrees down; or 0.5 m under it.
    std::vector<std::string> camera;
    if (std::string(GetParam()) == "below") camera.push_back("camera.position=[0,-0.5,2]");
    std::vector<std::string> tiled = camera;
    tiled.push_back(R"(floor.tiles={"side":0.25,"grout":0.02,"grout_albedo":[0.2,0.2,0.2]})");
    const Scene scene = builtin_scene("calm.json", tiled);
    Renderer renderer(context());
    const RenderOptions options{kWidth, kHeight, true, fg::TimingMode::None};
    const RenderResult real_time = renderer.render(scene, options);
    const RenderResult untiled = renderer.render(builtin_scene("calm.json", camera), options);
    const ImageRGBA32F reference = ref::render_reference(scene, {kWidth, kHeight, 0, {}});
    int flipped = 0, grout = 0;
    ImageRGBA32F mask;  // R = 1: a pixel whose two colours agree in kind (counted_pixels)
    mask.width = int(kWidth);
    mask.height = int(kHeight);
    mask.rgba.assign(size_t{kWidth} * kHeight * 4, 1.0f);
    for (size_t i = 0; i < mask.pixel_count(); ++i) {
        for (int c = 0; c < 3; ++c) {
            const double ref = reference.rgba[i * 4 + c];
            if (std::abs(real_time.image.rgba[i * 4 + c] - ref) > 1e-3 * std::max(ref, 1e-3)) mask.rgba[i * 4] = 0.0f;
        }
        flipped += mask.rgba[i * 4] == 0.0f;
        grout += real_time.image.rgba[i * 4 + 1] < 0.8f * untiled.image.rgba[i * 4 + 1];
    }
    EXPECT_LE(flipped, 1) << GetParam();
    const auto pixels = metrics::counted_pixels(kWidth, kHeight, &mask);
    EXPECT_LT(metrics::rel_mse(metrics::rgb_view(real_time.image), metrics::rgb_view(reference), pixels), 1e-10);
    // The tiles are there: grout 2 cm of every 25 cm covers 1 - (23/25)^2 = 15% of the floor.
    EXPECT_GT(grout, int(kWidth * kHeight) / 20) << GetParam();
}

INSTANTIATE_TEST_SUITE_P(Cameras, TiledFloor, ::testing::Values("above", "below"),
                         [](const auto& param_info) { return std::string(param_info.param); });

using WaterBody = GpuTest;

TEST_F(WaterBody, RaysFromTheWaterThatMeetNothingSeeNothing) {
    // Under flat water in a 4 m pool, looking level: the rays below the horizon that pass the
    // floor's edge leave the water body through its side and meet nothing, which the model
    // makes black (docs/model.md section 1), not the sky. Where the reference is black the real-time
    // image must be exactly black too, but for pixels next to a lit one (the floor's far edge is
    // a rasterised edge in one renderer and a ray test in the other: its row can differ by one).
    const Scene scene = parse_scene(R"({
      "camera": {"position": [0, -0.5, 1.5], "target": [0, -0.55, -5], "fov_y_deg": 60},
      "sun": {"elevation_deg": 60, "irradiance": [2, 2, 2]},
      "sky": {"radiance": [0.4, 0.5, 0.6]},
      "floor": {"height": -1, "half_extent": 2},
      "water": {"level": 0, "half_extent": 2, "waves": {"model": "flat"}},
      "medium": {"preset": "clear-ocean"}
    })",
                                    "pool_edge.json");
    Renderer renderer(context());
    const RenderResult real_time = renderer.render(scene, {kWidth, kHeight, true, fg::TimingMode::None});
    const ImageRGBA32F reference = ref::render_reference(scene, {kWidth, kHeight, 0, {}});
    const auto black = [](const ImageRGBA32F& image, int x, int y) {
        const float* p = image.pixel(x, y);
        return p[0] == 0.0f && p[1] == 0.0f && p[2] == 0.0f;
    };
    int black_in_reference = 0, lit_in_real_time = 0;
    for (int y = 0; y < int(kHeight); ++y) {
        for (int x = 0; x < int(kWidth); ++x) {
            if (!black(reference, x, y)) continue;
            ++black_in_reference;
            bool next_to_lit = false;
            for (int dy = -1; dy <= 1; ++dy) {
                for (int dx = -1; dx <= 1; ++dx) {
                    const int u = x + dx, v = y + dy;
                    next_to_lit = next_to_lit ||
                                  (u >= 0 && v >= 0 && u < int(kWidth) && v < int(kHeight) && !black(reference, u, v));
                }
            }
            if (!next_to_lit && !black(real_time.image, x, y)) ++lit_in_real_time;
        }
    }
    ASSERT_GT(black_in_reference, 100) << "too few rays leave the water in this view";
    EXPECT_EQ(lit_in_real_time, 0) << "of " << black_in_reference << " black reference pixels";
}

// Infinite flat water (docs/model.md section 1, "Infinite water") over a floor only 2 m wide, from
// calm's camera: the refracted rays past the floor run to the water's bottom and bring that path's
// in-scatter, in both renderers. Flat water leaves the shading no approximation, so the bound is
// the fp32 one of FlatWaterMatchesToFp32Rounding; and most of the water pixels are such rays.
TEST_F(WaterBody, InfiniteFlatWaterMatchesToFp32Rounding) {
    const Scene scene = builtin_scene("calm.json", {"water.half_extent=\"infinite\"", "floor.half_extent=2"});
    ASSERT_TRUE(scene.water->infinite);
    Renderer renderer(context());
    const auto [real_time, reference] = both_renderers(renderer, scene);
    expect_fp32_rounding_apart(real_time, reference, "infinite flat water");
    const auto pixels = metrics::counted_pixels(kWidth, kHeight, nullptr);
    // Not the water of a 20 m square either: calm's own image differs.
    const RenderResult finite = renderer.render(builtin_scene("calm.json", {"floor.half_extent=2"}),
                                                {kWidth, kHeight, true, fg::TimingMode::None});
    EXPECT_GT(metrics::rel_mse(metrics::rgb_view(finite.image), metrics::rgb_view(reference), pixels), 1e-6);
}

// A camera 1 m under infinite flat water looking 17 degrees down past a floor only 2 m wide: the
// rays below the horizon that meet nothing run to the water's bottom (or the far field) and bring
// that path's in-scatter, from the sky pass, in both renderers; the rays above it meet the surface
// from below. The bound is the fp32 one of FlatWaterMatchesToFp32Rounding. Before this rule those
// pixels were black in both, so each pixel is also asked to be lit.
TEST_F(WaterBody, CameraUnderInfiniteWaterSeesTheRunToTheBottom) {
    const Scene scene = builtin_scene(
        "calm.json", {"water.half_extent=\"infinite\"", "floor.half_extent=2", "camera.position=[0, -1, 0]",
                      "camera.direction=[0, -0.3, -1]", "camera.far=100000"});
    Renderer renderer(context());
    const auto [real_time, reference] = both_renderers(renderer, scene);
    expect_fp32_rounding_apart(real_time, reference, "camera under infinite water");
    uint32_t dark = 0;
    for (uint32_t y = 0; y < kHeight; ++y) {
        for (uint32_t x = 0; x < kWidth; ++x) dark += real_time.pixel(x, y)[2] > 0.0f ? 0 : 1;
    }
    EXPECT_EQ(dark, 0u);
}

using WaterRule = GpuTest;

TEST_F(WaterRule, CulledWaterImageEqualsForcedOnImage) {
    // Looking away from the water: the rule culls the water passes; forcing them on must
    // not change a pixel (nothing they draw is in view), so the images are equal exactly.
    const std::vector<std::string> away = {"camera.position=[0, 2, 30]", "camera.target=[0, 2, 60]"};
    std::vector<std::string> forced = away;
    forced.push_back("effects.water.mode=on");
    Renderer renderer(context());
    const RenderResult culled =
        renderer.render(builtin_scene("pool.json", away), {kWidth, kHeight, true, fg::TimingMode::None});
    const size_t pipelines_culled = renderer.pipelines().size();
    const RenderResult forced_on =
        renderer.render(builtin_scene("pool.json", forced), {kWidth, kHeight, true, fg::TimingMode::None});
    EXPECT_GT(renderer.pipelines().size(), pipelines_culled) << "forcing the water on created no water pipeline";
    EXPECT_EQ(culled.image.rgba, forced_on.image.rgba);
}

TEST_F(WaterRule, CulledCausticBlurImageEqualsForcedOnImage) {
    // caustic_blur.radius = 0 (the default): the rule culls the blur. Forced on, its two passes
    // run with every width h = 1, the identity (each texel keeps its value times 1 / 1), so the
    // images are equal exactly.
    Renderer renderer(context());
    const RenderResult culled =
        renderer.render(builtin_scene("pool.json"), {kWidth, kHeight, true, fg::TimingMode::None});
    const size_t pipelines_culled = renderer.pipelines().size();
    const RenderResult forced_on = renderer.render(builtin_scene("pool.json", {"effects.caustic_blur.mode=on"}),
                                                   {kWidth, kHeight, true, fg::TimingMode::None});
    EXPECT_GT(renderer.pipelines().size(), pipelines_culled) << "forcing the blur on created no pipeline";
    EXPECT_EQ(culled.image.rgba, forced_on.image.rgba);
}

TEST_F(WaterRule, CulledCausticsImageEqualsForcedOnImage) {
    // The sun below the horizon: the rule culls the caustic passes. Forced on, they trace
    // photons that all drop (no sunlight), and the map replaces a stand-in that is 0 too:
    // the same arithmetic on the same zeros, so the images are equal exactly.
    const std::vector<std::string> night = {"sun.elevation_deg=-5"};
    std::vector<std::string> forced = night;
    forced.push_back("effects.caustics.mode=on");
    Renderer renderer(context());
    const RenderResult culled =
        renderer.render(builtin_scene("pool.json", night), {kWidth, kHeight, true, fg::TimingMode::None});
    const size_t pipelines_culled = renderer.pipelines().size();
    const RenderResult forced_on =
        renderer.render(builtin_scene("pool.json", forced), {kWidth, kHeight, true, fg::TimingMode::None});
    EXPECT_GT(renderer.pipelines().size(), pipelines_culled) << "forcing the caustics on created no pipeline";
    EXPECT_EQ(culled.image.rgba, forced_on.image.rgba);
}

}  // namespace
}  // namespace vkw::test
