// The frame graph on a real device (lavapipe on CI), with validation and
// synchronization validation, in both recording kinds: a compute pass writes a
// storage image, a graphics pass samples it into an attachment, a transfer pass
// copies that into a host buffer. The pixels must be exact and validation silent.
// A second test removes one derived barrier in VkRenderPass recording and expects
// synchronization validation to report the hazard (proof that the test can fail;
// Debian's layers do not check dynamic-rendering attachments).
#include "engine/framegraph/executor.hpp"
#include "engine/framegraph/frame_graph.hpp"
#include "engine/framegraph/pass_context.hpp"
#include "engine/vk/resources.hpp"
#include "passes/present/readback.hpp"
#include "tests/support/gpu_test.hpp"
#include "tools/benchmarks/chain_graph.hpp"

#include <algorithm>
#include <cstring>

namespace vkw::test {
namespace {

constexpr uint32_t kWidth = 16;
constexpr uint32_t kHeight = 8;
constexpr VkDeviceSize kReadbackBytes = VkDeviceSize{kWidth} * kHeight * 4 * sizeof(float);

std::vector<float> read_floats(const Buffer& buffer) {
    std::vector<float> values(kReadbackBytes / sizeof(float));
    std::memcpy(values.data(), buffer.mapped(), kReadbackBytes);
    return values;
}

class FrameGraphChain : public GpuTest, public ::testing::WithParamInterface<fg::RecordingKind> {};

TEST_P(FrameGraphChain, ComputeSampleCopyGivesExactPixelsAndNoValidationMessages) {
    Buffer readback(context(), {kReadbackBytes, VK_BUFFER_USAGE_TRANSFER_DST_BIT, true}, "test readback");
    std::vector<float> pixels;
    {
        fg::PipelineStore pipelines;
        fg::FrameGraph graph;
        graph.set_default_recording(GetParam());
        passes::add_readback_pass(graph, chain::add_chain(graph), readback.handle(), kReadbackBytes);
        graph.compile(kWidth, kHeight);
        fg::FrameExecutor executor(context(), graph, pipelines, {.check_finite = true, .timing = fg::TimingMode::None});
        executor.execute();
        pixels = read_floats(readback);
    }
    for (uint32_t y = 0; y < kHeight; ++y) {
        for (uint32_t x = 0; x < kWidth; ++x) {
            const float* p = &pixels[4 * (y * kWidth + x)];
            // Small integers and their doubles are exact in fp32: equality, no tolerance.
            EXPECT_EQ(p[0], 2.0f * x) << "texel " << x << "," << y;
            EXPECT_EQ(p[1], 2.0f * y) << "texel " << x << "," << y;
            EXPECT_EQ(p[2], 2.0f * (x + y)) << "texel " << x << "," << y;
            EXPECT_EQ(p[3], 2.0f) << "texel " << x << "," << y;
        }
    }
}

INSTANTIATE_TEST_SUITE_P(BothRecordingKinds, FrameGraphChain,
                         ::testing::Values(fg::RecordingKind::DynamicRendering, fg::RecordingKind::RenderPassObject),
                         [](const auto& param_info) {
                             return param_info.param == fg::RecordingKind::DynamicRendering ? "DynamicRendering"
                                                                                            : "RenderPassObject";
                         });

using FrameGraphHazard = GpuTest;

// Pass "clear" clears an attachment; pass "accumulate" loads it. Between two render
// pass instances nothing orders the clear's write before the load's read except the
// graph's barrier; without it, synchronization validation must see READ_AFTER_WRITE.
void add_clear_then_load(fg::FrameGraph& graph, VkBuffer readback) {
    struct Data {
        fg::ImageHandle target;
    };
    const auto& clear = graph.add_pass<Data>(
        "clear", fg::PassKind::Graphics,
        [](fg::PassBuilder& builder, Data& d) {
            d.target = builder.create_image("target", {VK_FORMAT_R32G32B32A32_SFLOAT});
            d.target = builder.color_attachment(d.target, fg::LoadOp::Clear, {{0.25f, 0.5f, 0.75f, 1.0f}});
        },
        [](const Data&, fg::PassContext&) {});
    const auto& load = graph.add_pass<Data>(
        "accumulate", fg::PassKind::Graphics,
        [&](fg::PassBuilder& builder, Data& d) { d.target = builder.color_attachment(clear.target, fg::LoadOp::Load); },
        [](const Data&, fg::PassContext&) {});
    passes::add_readback_pass(graph, load.target, readback, kReadbackBytes);
}

// Runs add_clear_then_load in VkRenderPass recording, without the graph's barrier before
// "accumulate"'s load when `drop_barrier`. Returns once the executor is gone (idle device).
void run_clear_then_load(Context& context, VkBuffer readback, bool drop_barrier) {
    fg::PipelineStore pipelines;
    fg::FrameGraph graph;
    graph.set_default_recording(fg::RecordingKind::RenderPassObject);
    add_clear_then_load(graph, readback);
    graph.compile(kWidth, kHeight);
    fg::FrameExecutor executor(context, graph, pipelines, {.check_finite = true, .timing = fg::TimingMode::None});
    if (drop_barrier) executor.drop_barrier_for_test("accumulate", "target");
    executor.execute();
}

TEST_F(FrameGraphHazard, DerivedBarriersKeepRenderPassRecordingHazardFree) {
    Buffer readback(context(), {kReadbackBytes, VK_BUFFER_USAGE_TRANSFER_DST_BIT, true}, "test readback");
    run_clear_then_load(context(), readback.handle(), /*drop_barrier=*/false);
    const std::vector<float> pixels = read_floats(readback);
    EXPECT_EQ(pixels[0], 0.25f);  // the clear value, exactly representable
    EXPECT_EQ(pixels[2], 0.75f);
}

TEST_F(FrameGraphHazard, RemovedBarrierIsReportedBySynchronizationValidation) {
    Buffer readback(context(), {kReadbackBytes, VK_BUFFER_USAGE_TRANSFER_DST_BIT, true}, "test readback");
    run_clear_then_load(context(), readback.handle(), /*drop_barrier=*/true);
    readback = Buffer();
    const std::vector<std::string> messages = finish_and_collect_validation();
    const bool hazard = std::any_of(messages.begin(), messages.end(), [](const std::string& m) {
        return m.find("SYNC-HAZARD-READ-AFTER-WRITE") != std::string::npos ||
               m.find("SYNC-HAZARD-WRITE-AFTER-WRITE") != std::string::npos;
    });
    EXPECT_TRUE(hazard) << "validation reported " << messages.size() << " message(s), none a sync hazard";
}

}  // namespace
}  // namespace vkw::test
