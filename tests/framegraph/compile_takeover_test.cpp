// Frame after frame: compile() with the last frame's graph, and a declaration into the storage of
// an older one. A declaration that compiles like the last one takes its compiled result over
// instead of deriving it again, and that result equals a fresh compilation of the same
// declaration in every field; anything compile() reads that differs derives it anew. A graph
// cleared and declared again equals a new graph of the same declaration, and what its passes
// captured lives until it is cleared.
#include "tests/framegraph/framegraph_test_support.hpp"

#include <array>
#include <cstdint>
#include <memory>
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
    int extra_passes = 0;                                 // living passes beside the chain
    VkBuffer readback = VK_NULL_HANDLE;                   // the imported readback's handle
};

// simulate -> shade -> tone map -> readback, beside a godray pass the needs may cull and a pass
// whose output nobody reads (always culled): the tone map's target reuses the heights' memory, and
// the passes are culled for both reasons.
void declare(FrameGraph& graph, const Frame& frame) {
    ImportedBuffer readback_import = readback_buffer();
    readback_import.buffer = frame.readback;
    const BufferHandle readback = graph.import_buffer("readback", readback_import);
    for (int i = 0; i < frame.extra_passes; ++i) {
        add_pass(graph, "extra " + std::to_string(i), PassKind::Compute, [&](PassBuilder& b) {
            (void)b.write_storage("Extra", b.create_buffer("extra buffer " + std::to_string(i), {256}), kCompute);
            b.note("extra pass " + std::to_string(i) + " of " + std::to_string(frame.extra_passes));
            b.side_effect();
        });
    }
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

// What printing shows of a declaration that compile() does not read: the passes' notes and the
// regions their writes leave defined.
void expect_same_notes_and_regions(const FrameGraph& a, const FrameGraph& b) {
    ASSERT_EQ(a.passes().size(), b.passes().size());
    for (size_t p = 0; p < a.passes().size(); ++p) {
        EXPECT_EQ(a.passes()[p].note, b.passes()[p].note) << a.passes()[p].name;
        ASSERT_EQ(a.passes()[p].uses.size(), b.passes()[p].uses.size()) << a.passes()[p].name;
        for (size_t u = 0; u < a.passes()[p].uses.size(); ++u) {
            const std::optional<VkRect2D>&x = a.passes()[p].uses[u].defined_region,
                  &y = b.passes()[p].uses[u].defined_region;
            ASSERT_EQ(x.has_value(), y.has_value()) << a.passes()[p].name;
            if (x) {
                EXPECT_EQ(x->extent.width, y->extent.width);
                EXPECT_EQ(x->extent.height, y->extent.height);
            }
        }
    }
}

TEST(framegraph_redeclare, AClearedGraphDeclaresWhatANewOneDoes) {
    Frame more;
    more.extra_passes = 3;  // more passes and resources than the cleared graph kept
    Frame needed;
    needed.godrays_needed = true;
    needed.defined = {{0, 0}, {16, 64}};
    const std::vector<std::pair<Frame, Frame>> sequences = {
        {Frame{}, more}, {more, Frame{}}, {needed, Frame{}}, {Frame{}, needed}, {Frame{}, Frame{}}};
    for (const auto& [first, second] : sequences) {
        FrameGraph graph(needs_of(first));
        declare(graph, first);
        graph.compile(64, 64);
        graph.clear(needs_of(second));
        EXPECT_FALSE(graph.is_compiled());
        EXPECT_TRUE(graph.passes().empty());
        EXPECT_TRUE(graph.resources().empty());
        declare(graph, second);
        graph.compile(64, 64);
        EXPECT_FALSE(graph.took_over_compilation());
        const Compiled fresh(second);
        EXPECT_TRUE(graph.compiles_like(fresh.graph));
        EXPECT_TRUE(fresh.graph.compiles_like(graph));
        expect_same_compilation(graph, fresh.graph);
        expect_same_notes_and_regions(graph, fresh.graph);
    }
}

TEST(framegraph_redeclare, WhatThePassesCapturedLivesUntilTheGraphIsCleared) {
    const auto token = std::make_shared<int>(7);  // each capture holds one count of it
    struct Data {
        int index = -1;
        std::vector<int> list;
    };
    // Captures larger than the arena's block, and enough of them to fill several blocks.
    struct Large {
        std::array<char, 1024> bytes{};
    };
    struct Huge {
        std::array<char, 40 * 1024> bytes{};
    };
    constexpr int kPasses = 40;
    const auto declare_captures = [&](FrameGraph& graph) {
        std::vector<const Data*> data;
        for (int i = 0; i < kPasses; ++i) {
            const auto setup = [&](PassBuilder& b, Data& d) {
                d.index = i;
                d.list.assign(static_cast<size_t>(i), i);
                b.side_effect();
            };
            if (i % 10 == 9) {
                data.push_back(&graph.add_pass<Data>("pass " + std::to_string(i), PassKind::Compute, setup,
                                                     [token, huge = Huge{}](const Data&, PassContext&) {}));
            } else {
                data.push_back(&graph.add_pass<Data>("pass " + std::to_string(i), PassKind::Compute, setup,
                                                     [token, large = Large{}](const Data&, PassContext&) {}));
            }
        }
        // Every pass's Data where add_pass left it, after all the later passes were made.
        for (int i = 0; i < kPasses; ++i) {
            EXPECT_EQ(data[i]->index, i);
            EXPECT_EQ(data[i]->list, std::vector<int>(static_cast<size_t>(i), i));
            EXPECT_TRUE(graph.passes()[i].execute) << "pass " << i << " has no execute function";
        }
    };
    {
        FrameGraph graph;
        declare_captures(graph);
        EXPECT_EQ(token.use_count(), 1 + kPasses);
        graph.clear({});
        EXPECT_EQ(token.use_count(), 1) << "clear() kept what the passes captured";
        declare_captures(graph);
        EXPECT_EQ(token.use_count(), 1 + kPasses);
    }
    EXPECT_EQ(token.use_count(), 1) << "the graph's end kept what its passes captured";
}

TEST(framegraph_redeclare, AGraphThatTookTheCompilationOverKeepsTheSignatureWhileItsImportsStay) {
    const std::string signature = Compiled(Frame{}).graph.physical_signature();
    {
        Compiled last(Frame{});
        Compiled next({}, &last.graph);
        ASSERT_TRUE(next.graph.took_over_compilation());
        EXPECT_TRUE(next.graph.keeps_physical_signature_of(&last.graph));
        EXPECT_EQ(next.graph.physical_signature(), signature);
        EXPECT_FALSE(next.graph.keeps_physical_signature_of(nullptr));
        EXPECT_FALSE(last.graph.keeps_physical_signature_of(&next.graph)) << "the wrong way round";
    }
    {
        // Another readback buffer: compile() never reads the handle, the signature does.
        Compiled last(Frame{});
        Frame moved;
        moved.readback = reinterpret_cast<VkBuffer>(uintptr_t{0x40});
        Compiled next(moved, &last.graph);
        ASSERT_TRUE(next.graph.took_over_compilation());
        EXPECT_FALSE(next.graph.keeps_physical_signature_of(&last.graph));
        EXPECT_NE(next.graph.physical_signature(), signature);
    }
    {
        // Another default recording.
        Compiled last(Frame{});
        FrameGraph next(needs_of(Frame{}));
        declare(next, Frame{});
        next.set_default_recording(RecordingKind::RenderPassObject);
        next.compile(64, 64, &last.graph);
        EXPECT_FALSE(next.keeps_physical_signature_of(&last.graph));
    }
    {
        // A graph compiled afresh settles nothing without its signature.
        Compiled last(Frame{});
        Frame needed;
        needed.godrays_needed = true;
        Compiled next(needed, &last.graph);
        ASSERT_FALSE(next.graph.took_over_compilation());
        EXPECT_FALSE(next.graph.keeps_physical_signature_of(&last.graph));
    }
}

}  // namespace
}  // namespace vkw::fg::test
