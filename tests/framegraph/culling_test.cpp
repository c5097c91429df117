// FrameGraph culling (unread outputs, side effects, requested outputs, effects the
// frame does not need) and the execution order of the passes that survive.
#include "tests/framegraph/framegraph_test_support.hpp"

namespace vkw::fg::test {
namespace {

// A compute pass that writes a new image `name` and, if given, samples `input`.
ImageHandle add_compute(FrameGraph& graph, const std::string& pass, const std::string& name, ImageHandle input = {}) {
    ImageHandle output;
    add_pass(graph, pass, PassKind::Compute, [&](PassBuilder& builder) {
        if (input.valid()) builder.sample(input);
        output = builder.write_storage(builder.create_image(name, small_image()));
    });
    return output;
}

// The caustic chain: trace -> splat (serves SurfaceCaustics) -> receivers (side effect).
// `receivers_read_caustics` makes the living receivers pass read the splat's output.
void add_caustic_chain(FrameGraph& graph, bool receivers_read_caustics) {
    const ImageHandle photons = add_compute(graph, "trace", "photons");
    ImageHandle caustics;
    add_pass(graph, "splat", PassKind::Graphics, [&](PassBuilder& builder) {
        builder.serves(Effect::SurfaceCaustics);
        builder.sample(photons);
        caustics = builder.color_attachment(builder.create_image("caustics", small_image()));
    });
    add_pass(graph, "receivers", PassKind::Graphics, [&](PassBuilder& builder) {
        builder.side_effect();
        if (receivers_read_caustics) builder.sample(caustics);
        (void)builder.color_attachment(builder.create_image("hdr", small_image()));
    });
}

FrameNeeds caustics_off(bool forced) {
    FrameNeeds needs;
    needs.decide(Effect::SurfaceCaustics, false, "sun below the horizon", forced);
    return needs;
}

TEST(framegraph_culling, UnreadOutputCullsPassNamingItsOutputs) {
    FrameGraph graph;
    add_pass(graph, "orphan", PassKind::Graphics, [&](PassBuilder& builder) {
        (void)builder.color_attachment(builder.create_image("scratch_a", small_image()));
        (void)builder.write_storage(builder.create_image("scratch_b", small_image()));
    });
    graph.compile(64, 64);
    EXPECT_TRUE(order_names(graph).empty());
    const std::string reason = culled_reason(graph, "orphan");
    expect_contains(reason, {"'scratch_a'", "'scratch_b'"});
}

TEST(framegraph_culling, SideEffectKeepsPass) {
    FrameGraph graph;
    add_pass(graph, "writes_file", PassKind::Compute, [&](PassBuilder& builder) {
        builder.side_effect();
        (void)builder.write_storage(builder.create_image("unread", small_image()));
    });
    graph.compile(64, 64);
    EXPECT_EQ(order_names(graph), (std::vector<std::string>{"writes_file"}));
    EXPECT_TRUE(graph.compiled().culled.empty());
}

TEST(framegraph_culling, RequestedOutputKeepsProducerChain) {
    FrameGraph graph;
    const ImageHandle a = add_compute(graph, "make_a", "a");
    const ImageHandle b = add_compute(graph, "make_b", "b", a);
    const ImageHandle c = add_compute(graph, "make_c", "c", b);
    add_compute(graph, "unrelated", "d");
    graph.request_output(c);
    graph.compile(64, 64);
    EXPECT_EQ(order_names(graph), (std::vector<std::string>{"make_a", "make_b", "make_c"}));
    ASSERT_EQ(graph.compiled().culled.size(), 1u);
    EXPECT_EQ(graph.compiled().culled[0].name, "unrelated");
}

TEST(framegraph_culling, WithoutRequestWholeChainIsCulled) {
    FrameGraph graph;
    const ImageHandle a = add_compute(graph, "make_a", "a");
    add_compute(graph, "make_b", "b", a);
    graph.compile(64, 64);
    EXPECT_TRUE(order_names(graph).empty());
    EXPECT_EQ(graph.compiled().culled.size(), 2u);
}

TEST(framegraph_culling, UnneededEffectCullsPassWithDecisionReason) {
    FrameGraph graph(caustics_off(/*forced=*/false));
    add_caustic_chain(graph, /*receivers_read_caustics=*/false);
    graph.compile(64, 64);
    EXPECT_EQ(order_names(graph), (std::vector<std::string>{"receivers"}));
    const std::string splat = culled_reason(graph, "splat");
    expect_contains(splat, {"caustics", "sun below the horizon"});
    EXPECT_EQ(splat.find("(forced off)"), std::string::npos) << splat;
    // The producer that only fed the culled pass goes with it.
    expect_contains(culled_reason(graph, "trace"), {"'photons'"});
}

TEST(framegraph_culling, ForcedOffEffectSaysSo) {
    FrameGraph graph(caustics_off(/*forced=*/true));
    add_caustic_chain(graph, /*receivers_read_caustics=*/false);
    graph.compile(64, 64);
    expect_contains(culled_reason(graph, "splat"), {"caustics", "(forced off)", "sun below the horizon"});
}

TEST(framegraph_culling, LivingReaderOfEffectCulledPassIsAnError) {
    FrameGraph graph(caustics_off(/*forced=*/false));
    add_caustic_chain(graph, /*receivers_read_caustics=*/true);
    const std::string message = internal_error_of([&] { graph.compile(64, 64); });
    expect_contains(message, {"'receivers'", "'splat'", "'caustics'", "sun below the horizon"});
}

TEST(framegraph_culling, NeededEffectKeepsItsPasses) {
    FrameNeeds needs;
    needs.decide(Effect::SurfaceCaustics, true, "sun above the water");
    FrameGraph graph(needs);
    add_caustic_chain(graph, /*receivers_read_caustics=*/true);
    graph.compile(64, 64);
    EXPECT_EQ(order_names(graph), (std::vector<std::string>{"trace", "splat", "receivers"}));
}

TEST(framegraph_ordering, LivingPassesKeepDeclarationOrderAroundCulledOnes) {
    FrameGraph graph;
    const ImageHandle a = add_compute(graph, "first", "a");
    add_compute(graph, "dead", "unused", a);
    const ImageHandle b = add_compute(graph, "second", "b", a);
    const ImageHandle c = add_compute(graph, "third", "c", b);
    graph.request_output(c);
    graph.compile(64, 64);
    EXPECT_EQ(order_names(graph), (std::vector<std::string>{"first", "second", "third"}));
}

// exposes bug: compile() orders a DAG whose resource-version nodes all have ids above
// the passes', so a pass with no inputs ("sky") overtakes an earlier-declared pass that
// waits on a version node ("surface"): the order is first, sky, surface, water.
TEST(framegraph_ordering, IndependentPassDoesNotOvertakeEarlierOne) {
    FrameGraph graph;
    const ImageHandle constants = add_compute(graph, "first", "constants");
    const ImageHandle surface = add_compute(graph, "surface", "height", constants);
    const ImageHandle sky = add_compute(graph, "sky", "sky");
    add_pass(graph, "water", PassKind::Graphics, [&](PassBuilder& builder) {
        builder.sample(surface);
        builder.sample(sky);
        graph.request_output(builder.color_attachment(builder.create_image("color", small_image())));
    });
    graph.compile(64, 64);
    EXPECT_EQ(order_names(graph), (std::vector<std::string>{"first", "surface", "sky", "water"}));
}

// exposes bug: same cause, with a write-after-read hazard: "overwrite" (no inputs) is
// ordered before "read_history", which then samples the new contents, not last frame's.
TEST(framegraph_ordering, ReaderOfImportedImageRunsBeforeItsOverwrite) {
    FrameGraph graph;
    const ImageHandle history = graph.import_image(
        "history", ImportedImage{VK_NULL_HANDLE, VK_NULL_HANDLE, 64, 64, VK_FORMAT_R32G32B32A32_SFLOAT,
                                 AccessState{kCompute, kStorageWrite, kGeneral}, std::nullopt});
    add_pass(graph, "read_history", PassKind::Graphics, [&](PassBuilder& builder) {
        builder.side_effect();
        builder.sample(history);
    });
    add_pass(graph, "overwrite", PassKind::Compute,
             [&](PassBuilder& builder) { graph.request_output(builder.write_storage(history)); });
    graph.compile(64, 64);
    EXPECT_EQ(order_names(graph), (std::vector<std::string>{"read_history", "overwrite"}));
}

}  // namespace
}  // namespace vkw::fg::test
