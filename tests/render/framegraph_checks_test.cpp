// Two promises of the frame graph on the device: the finite check names the pass,
// the resource and the texel of the first NaN/Inf a pass writes; and a culled pass
// never creates its pipeline (pipeline creation is the costly part on lavapipe).
#include "engine/core/errors.hpp"
#include "engine/framegraph/executor.hpp"
#include "engine/framegraph/pass_context.hpp"
#include "engine/scene/effects.hpp"
#include "passes/present/readback.hpp"
#include "tests/support/gpu_test.hpp"

#include <shader_structs/tests/poison.comp.hpp>

#include <optional>
#include <string>

namespace vkw::test {
namespace {

constexpr uint32_t kSize = 16;
constexpr VkDeviceSize kBytes = VkDeviceSize{kSize} * kSize * 16;

// tests/poison.comp's push block (its bad texel, channel, and whether the poison is +Inf or NaN).
using PoisonParams = glsl::poison_comp::Params;

// `defined`: the pass declares that it leaves only this region of its (then kSize x kSize
// absolute) image defined (PassBuilder::defines_only).
fg::ImageHandle add_poison_pass(fg::FrameGraph& graph, const std::string& name, PoisonParams params,
                                std::optional<VkRect2D> defined = std::nullopt) {
    struct Data {
        fg::ImageHandle image;
    };
    return graph
        .add_pass<Data>(
            name, fg::PassKind::Compute,
            [&](fg::PassBuilder& builder, Data& d) {
                const fg::ImageInfo info =
                    defined ? fg::ImageInfo{VK_FORMAT_R32G32B32A32_SFLOAT, fg::SizeClass::Absolute, 1.0f, kSize, kSize}
                            : fg::ImageInfo{VK_FORMAT_R32G32B32A32_SFLOAT};
                d.image = builder.write_storage("target", builder.create_image(name + " image", info));
                if (defined) builder.defines_only(d.image, *defined);
            },
            [params](const Data&, fg::PassContext& context) {
                ComputePipelineDesc desc;
                desc.shader = "tests/poison.comp";
                desc.layout.bindings = {{0, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE, 1, VK_SHADER_STAGE_COMPUTE_BIT}};
                desc.layout.push_constant_bytes = sizeof(PoisonParams);
                const Pipeline& pipeline = context.pipeline("poison", desc);
                context.bind(pipeline);
                context.push_constants(pipeline, params);
                vkCmdDispatch(context.cmd(), kSize / 8, kSize / 8, 1);
            })
        .image;
}

using FrameGraphChecks = GpuTest;

TEST_F(FrameGraphChecks, FiniteCheckNamesPassResourceAndTexel) {
    for (const uint32_t infinity : {0u, 1u}) {
        Buffer readback(context(), {kBytes, VK_BUFFER_USAGE_TRANSFER_DST_BIT, true}, "readback");
        fg::PipelineStore pipelines;
        fg::FrameGraph graph;
        // A clean pass first, then the poisoned one: the report must name the second.
        const fg::ImageHandle clean = add_poison_pass(graph, "clean", {{-1, -1}, 0, 0});
        graph.request_output(clean);
        const fg::ImageHandle bad = add_poison_pass(graph, "poison", {{5, 3}, 2, infinity});
        passes::add_readback_pass(graph, bad, readback.handle(), kBytes);
        graph.compile(kSize, kSize);
        fg::FrameExecutor executor(context(), graph, pipelines, {.check_finite = true, .timing = fg::TimingMode::None});
        try {
            executor.execute();
            FAIL() << "the finite check let a non-finite value through";
        } catch (const InternalError& error) {
            const std::string message = error.what();
            EXPECT_NE(message.find("pass 'poison'"), std::string::npos) << message;
            EXPECT_NE(message.find("'poison image'"), std::string::npos) << message;
            EXPECT_NE(message.find("texel (5, 3), channel 2"), std::string::npos) << message;
            EXPECT_NE(message.find(infinity ? "Inf" : "NaN"), std::string::npos) << message;
        }
    }
}

// A pass that defines only part of its image (the caustic resolve, which converts the texels the
// frame reads) is checked there alone: a NaN outside the region is not its output, one inside is
// named at its texel in the whole image.
TEST_F(FrameGraphChecks, FiniteCheckScansTheRegionAPassDefines) {
    for (const bool poison_inside : {false, true}) {
        Buffer readback(context(), {kBytes, VK_BUFFER_USAGE_TRANSFER_DST_BIT, true}, "readback");
        fg::PipelineStore pipelines;
        fg::FrameGraph graph;
        const VkRect2D region = poison_inside ? VkRect2D{{4, 2}, {4, 5}} : VkRect2D{{8, 0}, {8, kSize}};
        const fg::ImageHandle image = add_poison_pass(graph, "partial", {{5, 3}, 1, 0}, region);
        passes::add_readback_pass(graph, image, readback.handle(), kBytes);
        graph.compile(kSize, kSize);
        fg::FrameExecutor executor(context(), graph, pipelines, {.check_finite = true, .timing = fg::TimingMode::None});
        if (!poison_inside) {
            EXPECT_NO_THROW(executor.execute());
            continue;
        }
        try {
            executor.execute();
            FAIL() << "the finite check let a NaN inside the defined region through";
        } catch (const InternalError& error) {
            const std::string message = error.what();
            EXPECT_NE(message.find("texel (5, 3), channel 1"), std::string::npos) << message;
        }
    }
}

TEST_F(FrameGraphChecks, ARegionOutsideTheImageIsRefused) {
    fg::FrameGraph graph;
    EXPECT_THROW(add_poison_pass(graph, "partial", {{-1, -1}, 0, 0}, VkRect2D{{12, 0}, {8, 4}}), InternalError);
}

TEST_F(FrameGraphChecks, CulledPassCreatesNoPipeline) {
    Buffer readback(context(), {kBytes, VK_BUFFER_USAGE_TRANSFER_DST_BIT, true}, "readback");
    fg::PipelineStore pipelines;
    fg::FrameNeeds needs;
    needs.decide(Effect::VolumeCaustics, false, "test: not needed");
    fg::FrameGraph graph(needs);
    const fg::ImageHandle used = add_poison_pass(graph, "used", {{-1, -1}, 0, 0});
    add_poison_pass(graph, "unread", {{-1, -1}, 0, 0});  // nothing reads it
    struct Data {
        fg::ImageHandle image;
    };
    graph.add_pass<Data>(
        "godrays", fg::PassKind::Compute,
        [](fg::PassBuilder& builder, Data& d) {
            builder.serves(Effect::VolumeCaustics);
            builder.side_effect();  // even a side effect does not keep an unneeded effect's pass
            d.image = builder.write_storage(builder.create_image("godray image", {VK_FORMAT_R32G32B32A32_SFLOAT}));
        },
        [](const Data&, fg::PassContext& context) {
            context.pipeline("never", ComputePipelineDesc{"tests/poison.comp", {}});
        });
    passes::add_readback_pass(graph, used, readback.handle(), kBytes);
    graph.compile(kSize, kSize);
    fg::FrameExecutor executor(context(), graph, pipelines, {.check_finite = true, .timing = fg::TimingMode::None});
    executor.execute();
    EXPECT_EQ(pipelines.size(), 1u);
    EXPECT_TRUE(pipelines.contains("used/poison"));
    EXPECT_FALSE(pipelines.contains("unread/poison"));
    EXPECT_FALSE(pipelines.contains("godrays/never"));
    ASSERT_EQ(graph.compiled().culled.size(), 2u);
    EXPECT_EQ(graph.compiled().culled[1].reason, "effect 'godrays' not needed: test: not needed");
}

}  // namespace
}  // namespace vkw::test

namespace vkw::test {
namespace {

TEST_F(FrameGraphChecks, EveryTimingMethodReportsEachLivingPassOnce) {
    // Timestamps are the method for real GPUs; lavapipe has them too (they leave out its
    // raster work, which is why it defaults to fences), so the path runs here, validated.
    for (const fg::TimingMode mode : {fg::TimingMode::Timestamps, fg::TimingMode::Fences, fg::TimingMode::None}) {
        Buffer readback(context(), {kBytes, VK_BUFFER_USAGE_TRANSFER_DST_BIT, true}, "readback");
        fg::PipelineStore pipelines;
        fg::FrameGraph graph;
        passes::add_readback_pass(graph, add_poison_pass(graph, "fill", {{-1, -1}, 0, 0}), readback.handle(), kBytes);
        graph.compile(kSize, kSize);
        fg::FrameExecutor executor(context(), graph, pipelines, {.timing = mode});
        const fg::FrameReport report = executor.execute();
        EXPECT_EQ(report.method, mode);
        EXPECT_FALSE(report.method_name().empty());
        if (mode == fg::TimingMode::None) {
            EXPECT_TRUE(report.passes.empty());
        } else {
            ASSERT_EQ(report.passes.size(), 2u);
            EXPECT_EQ(report.passes[0].pass, "fill");
            EXPECT_EQ(report.passes[1].pass, "readback");
            for (const fg::PassTime& pass : report.passes) EXPECT_GE(pass.ms, 0.0) << pass.pass;
        }
        EXPECT_GT(report.total_ms, 0.0);
    }
}

}  // namespace
}  // namespace vkw::test
