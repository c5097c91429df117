// A pass names each shader resource once, in its declarations (PassBuilder's named uses), and
// PassContext::bind pushes every binding a pipeline's shaders use from them. What a pass gets
// wrong is an InternalError naming the pass and the binding, never an unset descriptor.
#include "engine/core/errors.hpp"
#include "engine/framegraph/executor.hpp"
#include "engine/framegraph/pass_context.hpp"
#include "passes/present/readback.hpp"
#include "tests/support/gpu_test.hpp"

#include <shader_structs/tests/poison.comp.hpp>

#include <cstring>
#include <functional>
#include <string>
#include <vector>

namespace vkw::test {
namespace {

constexpr uint32_t kSize = 16;
constexpr VkDeviceSize kBytes = VkDeviceSize{kSize} * kSize * 16;

// tests/poison.comp's push block (its bad texel, channel, and whether the poison is +Inf or NaN).
using PoisonParams = glsl::poison_comp::Params;

using DeclaredBindings = GpuTest;

// tests/poison.comp (one storage image, `target`) over a 16 x 16 image, declared by `declare` and
// bound by `bind`; the image read back into `pixels`.
void run_poison(Context& gpu, const std::function<fg::ImageHandle(fg::PassBuilder&, fg::ImageHandle)>& declare,
                const std::function<void(fg::PassContext&, const Pipeline&, fg::ImageHandle)>& bind,
                std::vector<float>* pixels = nullptr) {
    Buffer readback(gpu, {kBytes, VK_BUFFER_USAGE_TRANSFER_DST_BIT, true}, "readback");
    fg::PipelineStore pipelines;
    fg::FrameGraph graph;
    struct Data {
        fg::ImageHandle image;
    };
    const auto& data = graph.add_pass<Data>(
        "poison", fg::PassKind::Compute,
        [&](fg::PassBuilder& builder, Data& d) {
            d.image = declare(builder, builder.create_image("poison image", {VK_FORMAT_R32G32B32A32_SFLOAT}));
        },
        [&](const Data& d, fg::PassContext& context) {
            const Pipeline& pipeline = context.pipeline("poison", ComputePipelineDesc{"tests/poison.comp"});
            bind(context, pipeline, d.image);
            context.push_constants(pipeline, PoisonParams{{-1, -1}, 0, 0});  // no poisoned texel
            context.dispatch(pipeline, d.image);
        });
    passes::add_readback_pass(graph, data.image, readback.handle(), kBytes);
    graph.compile(kSize, kSize);
    fg::FrameExecutor executor(gpu, graph, pipelines, {.check_finite = true, .timing = fg::TimingMode::None});
    executor.execute();
    if (pixels) {
        pixels->resize(kSize * kSize * 4);
        std::memcpy(pixels->data(), readback.mapped(), kBytes);
    }
}

TEST_F(DeclaredBindings, ANamedDeclarationBindsItselfAndTheDispatchCoversTheImage) {
    std::vector<float> pixels;
    run_poison(
        context(),
        [](fg::PassBuilder& builder, fg::ImageHandle image) { return builder.write_storage("target", image); },
        [](fg::PassContext& context, const Pipeline& pipeline, fg::ImageHandle) { context.bind(pipeline); }, &pixels);
    // The shader writes 1.0 to every channel of every texel it reaches: each of the 16 x 16
    // texels, from 2 x 2 groups of the shader's 8 x 8, if the dispatch covered the image.
    for (size_t i = 0; i < pixels.size(); ++i) ASSERT_EQ(pixels[i], 1.0f) << "float " << i;
}

TEST_F(DeclaredBindings, ABindingNoDeclarationNamesThrowsNamingPassBindingAndType) {
    try {
        run_poison(
            context(), [](fg::PassBuilder& builder, fg::ImageHandle image) { return builder.write_storage(image); },
            [](fg::PassContext& context, const Pipeline& pipeline, fg::ImageHandle) { context.bind(pipeline); });
        FAIL() << "an undeclared binding was left unset";
    } catch (const InternalError& e) {
        EXPECT_EQ(std::string(e.what()),
                  "pass 'poison' declares no resource for 'target' (binding 0, a storage "
                  "image), which its shaders read");
    }
}

TEST_F(DeclaredBindings, ADescriptorOfTheWrongTypeThrowsNamingBoth) {
    try {
        run_poison(
            context(), [](fg::PassBuilder& builder, fg::ImageHandle image) { return builder.write_storage(image); },
            [](fg::PassContext& context, const Pipeline& pipeline, fg::ImageHandle image) {
                context.bind(pipeline, {context.sampled("target", image)});
            });
        FAIL() << "a sampler was written to a storage image's binding";
    } catch (const InternalError& e) {
        EXPECT_EQ(std::string(e.what()),
                  "pass 'poison' binds a combined image sampler to 'target' (binding 0), "
                  "where its pipeline's shaders read a storage image");
    }
}

TEST_F(DeclaredBindings, AnExtraDescriptorTakesThePlaceOfTheDeclaredOne) {
    std::vector<float> pixels;
    run_poison(
        context(),
        [](fg::PassBuilder& builder, fg::ImageHandle image) { return builder.write_storage("target", image); },
        [](fg::PassContext& context, const Pipeline& pipeline, fg::ImageHandle image) {
            context.bind(pipeline, {context.storage_image("target", image)});
        },
        &pixels);
    for (size_t i = 0; i < pixels.size(); ++i) ASSERT_EQ(pixels[i], 1.0f) << "float " << i;
}

TEST(DeclaredBindingNames, TwoResourcesUnderOneNameThrowAtDeclaration) {
    fg::FrameGraph graph;
    struct Data {};
    try {
        graph.add_pass<Data>(
            "twice", fg::PassKind::Compute,
            [](fg::PassBuilder& builder, Data&) {
                (void)builder.write_storage("target", builder.create_image("a", {}));
                (void)builder.write_storage("target", builder.create_image("b", {}));
            },
            [](const Data&, fg::PassContext&) {});
        FAIL() << "two resources were declared under one name";
    } catch (const InternalError& e) {
        EXPECT_EQ(std::string(e.what()), "pass 'twice' binds two resources to 'target'");
    }
}

}  // namespace
}  // namespace vkw::test
