// compile() with the last frame's graph: a declaration that compiles like the last one takes its
// compiled result over instead of deriving it again, and that result equals a fresh compilation
// of the same declaration in every field; anything compile() reads that differs derives it anew.
#include "tests/framegraph/framegraph_test_support.hpp"

#include <string>
#include <vector>

namespace vkw::fg::test {
namespace {

// What may differ between two frames' declarations.
struct Frame {
    bool godrays_needed = false;
    std::string godrays_reason = "the water is flat";
    VkPipelineStageFlags2 height_stages = kVertexShader;  // where 'shade' reads the heights
    float clear_red = 0.0f;                               // 'shade''s clear colour
    VkRect2D defined = {{0, 0}, {64, 64}};                // what 'shade' leaves defined
};

// simulate -> shade -> tone map -> readback, beside a godray pass the needs may cull and a pass
// whose output nobody reads (always culled): the tone map's target reuses the heights' memory, and
// the passes are culled for both reasons.
void declare(FrameGraph& graph, const Frame& frame) {
    const BufferHandle readback = graph.import_buffer("readback", readback_buffer());
    BufferHandle heights;
    add_pass(graph, "simulate", PassKind::Compute,
             [&](PassBuilder& b) { heights = b.write_storage(b.create_buffer("heights", {64 * 64 * 16}), kCompute); });
    add_pass(graph, "unused", PassKind::Compute,
             [&](PassBuilder& b) { (void)b.write_storage(b.create_buffer("scratch", {4096}), kCompute); });
    ImageHandle hdr;
    add_pass(graph, "shade", PassKind::Graphics, [&](PassBuilder& b) {
        b.read_storage(heights, frame.height_stages);
        ClearValue clear;
        clear.color[0] = frame.clear_red;
        hdr = b.color_attachment(b.create_image("hdr", small_image()), LoadOp::Clear, clear);
        b.defines_only(hdr, frame.defined);
    });
    add_pass(graph, "godrays", PassKind::Compute, [&](PassBuilder& b) {
        b.serves(Effect::VolumeCaustics);
        b.sample(hdr, kCompute);
        (void)b.write_storage(b.create_image("rays", small_image()), kCompute);
        b.side_effect();
    });
    ImageHandle ldr;
    add_pass(graph, "tone map", PassKind::Compute, [&](PassBuilder& b) {
        b.sample(hdr, kCompute);
        ldr = b.write_storage(b.create_image("ldr", small_image()), kCompute);
    });
    add_pass(graph, "readback", PassKind::Transfer, [&](PassBuilder& b) {
        b.copy_source(ldr);
        (void)b.copy_destination(readback);
        b.side_effect();
    });
}

FrameNeeds needs_of(const Frame& frame) {
    FrameNeeds needs;
    needs.decide(Effect::VolumeCaustics, frame.godrays_needed, frame.godrays_reason);
    return needs;
}

// A graph of `frame`, compiled at 64x64 (with the previous frame's graph, if given).
struct Compiled {
    FrameGraph graph;
    Compiled(const Frame& frame, FrameGraph* previous = nullptr, uint32_t size = 64) : graph(needs_of(frame)) {
        declare(graph, frame);
        graph.compile(size, size, previous);
    }
};

// Every field of the two compilations: the printed forms (order, culled passes and reasons,
// resources, lifetimes, aliasing, barriers) and the vectors they are printed from.
void expect_same_compilation(const FrameGraph& taken_over, const FrameGraph& fresh) {
    const CompiledGraph& a = taken_over.compiled();
    const CompiledGraph& b = fresh.compiled();
    EXPECT_EQ(taken_over.describe(), fresh.describe());
    EXPECT_EQ(taken_over.dump_barriers(), fresh.dump_barriers());
    EXPECT_EQ(barriers_of(taken_over), barriers_of(fresh));
    EXPECT_EQ(a.order, b.order);
    ASSERT_EQ(a.culled.size(), b.culled.size());
    for (size_t i = 0; i < a.culled.size(); ++i) {
        EXPECT_EQ(a.culled[i].name, b.culled[i].name);
        EXPECT_EQ(a.culled[i].reason, b.culled[i].reason);
    }
    EXPECT_EQ(a.resource_live, b.resource_live);
    EXPECT_EQ(a.first_use, b.first_use);
    EXPECT_EQ(a.last_use, b.last_use);
    EXPECT_EQ(a.aliasing, b.aliasing);
    EXPECT_EQ(a.aliased_resources, b.aliased_resources);
    ASSERT_EQ(a.timelines.size(), b.timelines.size());
    for (size_t r = 0; r < a.timelines.size(); ++r) {
        EXPECT_EQ(a.timelines[r].name, b.timelines[r].name);
        EXPECT_EQ(a.timelines[r].initial, b.timelines[r].initial) << a.timelines[r].name;
        EXPECT_EQ(a.timelines[r].final_state, b.timelines[r].final_state) << a.timelines[r].name;
        ASSERT_EQ(a.timelines[r].accesses.size(), b.timelines[r].accesses.size()) << a.timelines[r].name;
        for (size_t i = 0; i < a.timelines[r].accesses.size(); ++i) {
            EXPECT_EQ(a.timelines[r].accesses[i].position, b.timelines[r].accesses[i].position);
            EXPECT_EQ(a.timelines[r].accesses[i].state, b.timelines[r].accesses[i].state);
            EXPECT_EQ(a.timelines[r].accesses[i].writes, b.timelines[r].accesses[i].writes);
        }
    }
    EXPECT_EQ(taken_over.physical_signature(), fresh.physical_signature());
}

TEST(framegraph_takeover, TheSameDeclarationTakesTheLastResultOver) {
    Compiled last(Frame{});
    ASSERT_FALSE(last.graph.took_over_compilation());
    Compiled next({}, &last.graph);
    EXPECT_TRUE(next.graph.took_over_compilation());
    EXPECT_FALSE(last.graph.is_compiled()) << "the result was copied, not taken over";
    // The graph is not trivial: something is culled for each reason, and a transient reuses memory.
    EXPECT_EQ(order_names(next.graph), (std::vector<std::string>{"simulate", "shade", "tone map", "readback"}));
    const AliasPlan& aliasing = next.graph.compiled().aliasing;
    EXPECT_LT(aliasing.heap_size, aliasing.unaliased_size);
    expect_contains(culled_reason(next.graph, "godrays"), {"the water is flat"});
    expect_contains(culled_reason(next.graph, "unused"), {"'scratch'"});
    expect_same_compilation(next.graph, Compiled(Frame{}).graph);
}

TEST(framegraph_takeover, WhatCompileDoesNotReadMayChange) {
    // The needs' words (printed again with the new ones), the region a write leaves defined.
    Compiled last(Frame{});
    Frame frame;
    frame.godrays_reason = "the waves keep the beams within 0.1% of flat water's";
    frame.defined = {{0, 0}, {32, 64}};
    Compiled next(frame, &last.graph);
    EXPECT_TRUE(next.graph.took_over_compilation());
    expect_contains(culled_reason(next.graph, "godrays"), {"within 0.1% of flat water's"});
    expect_same_compilation(next.graph, Compiled(frame).graph);
}

TEST(framegraph_takeover, WhatCompileReadsDerivesItAgain) {
    Frame needed;
    needed.godrays_needed = true;
    Frame stages;
    stages.height_stages = kFragment;
    Frame clear;
    clear.clear_red = 1.0f;
    for (const Frame& frame : {needed, stages, clear}) {
        Compiled last(Frame{});
        Compiled next(frame, &last.graph);
        EXPECT_FALSE(next.graph.took_over_compilation());
        EXPECT_TRUE(last.graph.is_compiled());
        expect_same_compilation(next.graph, Compiled(frame).graph);
    }
    EXPECT_EQ(order_names(Compiled(needed).graph),
              (std::vector<std::string>{"simulate", "shade", "godrays", "tone map", "readback"}));

    // Another output size.
    Compiled last(Frame{});
    Compiled larger({}, &last.graph, 128);
    EXPECT_FALSE(larger.graph.took_over_compilation());
    EXPECT_EQ(larger.graph.compiled().output_width, 128u);

    // A previous graph that was never compiled, or that handed its result on already.
    FrameGraph declared_only(needs_of(Frame{}));
    declare(declared_only, Frame{});
    EXPECT_FALSE(Compiled(Frame{}, &declared_only).graph.took_over_compilation());
    Compiled first(Frame{});
    Compiled second({}, &first.graph);
    ASSERT_TRUE(second.graph.took_over_compilation());
    EXPECT_FALSE(Compiled(Frame{}, &first.graph).graph.took_over_compilation());
}

}  // namespace
}  // namespace vkw::fg::test
