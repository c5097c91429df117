// The resolution scale (passes/frame/upscale.hpp). A linear ramp stretched by the bilinear filter
// stays the same ramp, sampled where each output pixel's centre falls, and clamped to the edge
// texels' centres outside them: checked against that closed form in both recording kinds. The
// renderer at a scale below 1 hands back an image and layers of the requested size, finite, and
// at scale 1 it adds no pass.
#include "passes/frame/upscale.hpp"

#include "engine/framegraph/executor.hpp"
#include "engine/scene/scene_loader.hpp"
#include "engine/vk/resources.hpp"
#include "passes/frame/renderer.hpp"
#include "passes/present/readback.hpp"
#include "tests/support/gpu_test.hpp"
#include "tools/benchmarks/chain_graph.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <filesystem>

namespace vkw::test {
namespace {

// The chain's source: texel (x, y) holds (2x, 2y, 2(x + y), 2), at 16 x 8.
constexpr uint32_t kSourceWidth = 16, kSourceHeight = 8;
// Stretched by 2.5 across and 2.25 down: the output's pixel centres fall between the source's.
constexpr uint32_t kOutputWidth = 40, kOutputHeight = 18;

// Where output pixel i's centre falls in source texel coordinates (texel centres at integers),
// clamped to the first and last centres, as a clamp-to-edge bilinear sampler reads it.
double source_coordinate(uint32_t i, uint32_t output, uint32_t source) {
    const double at = (i + 0.5) * double(source) / double(output) - 0.5;
    return std::clamp(at, 0.0, double(source - 1));
}

class UpscaleRamp : public GpuTest, public ::testing::WithParamInterface<fg::RecordingKind> {};

TEST_P(UpscaleRamp, StretchesALinearRampToTheSameRamp) {
    const VkDeviceSize bytes = VkDeviceSize{kOutputWidth} * kOutputHeight * 4 * sizeof(float);
    Buffer readback(context(), {bytes, VK_BUFFER_USAGE_TRANSFER_DST_BIT, true}, "test readback");
    {
        fg::PipelineStore pipelines;
        fg::FrameGraph graph;
        graph.set_default_recording(GetParam());
        const fg::ImageHandle stretched =
            passes::add_upscale_pass(graph, chain::add_chain(graph), kOutputWidth, kOutputHeight, "upscale");
        passes::add_readback_pass(graph, stretched, readback.handle(), bytes);
        graph.compile(kSourceWidth, kSourceHeight);
        fg::FrameExecutor executor(context(), graph, pipelines, {.check_finite = true, .timing = fg::TimingMode::None});
        executor.execute();
    }
    std::vector<float> pixels(bytes / sizeof(float));
    std::memcpy(pixels.data(), readback.mapped(), bytes);
    // The filter's weights are fixed-point with subTexelPrecisionBits fraction bits: a weight is
    // off by at most 2^-bits, and neighbouring texels differ by 2 per axis, so each axis adds at
    // most 2 * 2^-bits; fp32 rounding of values below 50 adds less than 1e-5.
    const int bits = static_cast<int>(context().properties().limits.subTexelPrecisionBits);
    const double tolerance_per_axis = 2.0 * std::ldexp(1.0, -bits);
    for (uint32_t y = 0; y < kOutputHeight; ++y) {
        for (uint32_t x = 0; x < kOutputWidth; ++x) {
            const double u = source_coordinate(x, kOutputWidth, kSourceWidth);
            const double v = source_coordinate(y, kOutputHeight, kSourceHeight);
            const float* p = &pixels[4 * (y * kOutputWidth + x)];
            EXPECT_NEAR(p[0], 2.0 * u, tolerance_per_axis + 1e-5) << "pixel " << x << "," << y;
            EXPECT_NEAR(p[1], 2.0 * v, tolerance_per_axis + 1e-5) << "pixel " << x << "," << y;
            EXPECT_NEAR(p[2], 2.0 * (u + v), 2.0 * tolerance_per_axis + 1e-5) << "pixel " << x << "," << y;
            EXPECT_EQ(p[3], 2.0f) << "a constant stays exact";
        }
    }
}

INSTANTIATE_TEST_SUITE_P(BothRecordingKinds, UpscaleRamp,
                         ::testing::Values(fg::RecordingKind::DynamicRendering, fg::RecordingKind::RenderPassObject),
                         [](const auto& param_info) {
                             return param_info.param == fg::RecordingKind::DynamicRendering ? "DynamicRendering"
                                                                                            : "RenderPassObject";
                         });

TEST(UpscaleSize, RoundsTheScaledSideAndKeepsAtLeastOnePixel) {
    EXPECT_EQ(passes::scaled_size(800, 0.5), 400u);
    EXPECT_EQ(passes::scaled_size(600, 0.35), 210u);
    EXPECT_EQ(passes::scaled_size(3, 0.5), 2u);  // 1.5 rounds away from zero
    EXPECT_EQ(passes::scaled_size(10, 0.001), 1u);
    EXPECT_EQ(passes::scaled_size(799, 1.0), 799u);
}

using RenderScale = GpuTest;

bool has_pass(const fg::FrameReport& report, const std::string& name) {
    return std::any_of(report.passes.begin(), report.passes.end(),
                       [&](const fg::PassTime& pass) { return pass.pass == name; });
}

TEST_F(RenderScale, HandsBackTheRequestedSizeWithItsLayers) {
    // pool: waves, caustics and godrays, so all three images are stretched.
    const Scene scene = load_scene(std::filesystem::path(VKWATER_SOURCE_DIR) / "scenes/pool.json");
    RenderOptions options{64, 48, true, fg::TimingMode::Fences};
    options.caustic_layer = options.inscatter_layer = true;
    options.render_scale = 0.5;
    Renderer renderer(context());
    const RenderResult scaled = renderer.render(scene, options);
    ASSERT_EQ(scaled.image.width, 64);
    ASSERT_EQ(scaled.image.height, 48);
    ASSERT_EQ(scaled.image.layers.size(), 2u);
    EXPECT_TRUE(has_pass(scaled.timing, "upscale"));
    EXPECT_TRUE(has_pass(scaled.timing, "caustic layer upscale"));
    EXPECT_TRUE(has_pass(scaled.timing, "in-scatter layer upscale"));
    double sum = 0.0;
    for (float value : scaled.image.rgba) {
        ASSERT_TRUE(std::isfinite(value));
        sum += value;
    }
    EXPECT_GT(sum, 0.0) << "a lit pool is not black";

    options.render_scale = 1.0;
    const RenderResult full = renderer.render(scene, options);
    EXPECT_FALSE(has_pass(full.timing, "upscale"));
}

TEST_F(RenderScale, OutOfRangeIsTheUsersMistake) {
    const Scene scene = load_scene(std::filesystem::path(VKWATER_SOURCE_DIR) / "scenes/calm.json");
    RenderOptions options{64, 48, true, fg::TimingMode::None};
    Renderer renderer(context());
    for (double scale : {0.0, -0.5, 1.5, std::nan("")}) {
        options.render_scale = scale;
        EXPECT_THROW(renderer.render(scene, options), UserError) << scale;
    }
}

}  // namespace
}  // namespace vkw::test
