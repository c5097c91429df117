// Transient memory aliasing: plan_aliasing on hand-made requests (offsets, heap size,
// alignment, predecessors) and, through FrameGraph::compile, the heap of a chain of
// transients and the wait that memory reuse adds to the first barrier.
#include "tests/framegraph/framegraph_test_support.hpp"

#include <algorithm>

namespace vkw::fg::test {
namespace {

bool ranges_overlap(const AliasPlan& plan, const std::vector<AliasRequest>& requests, size_t a, size_t b) {
    return plan.offsets[a] < plan.offsets[b] + requests[b].size && plan.offsets[b] < plan.offsets[a] + requests[a].size;
}

TEST(framegraph_aliasing, DisjointLifetimesShareMemory) {
    const std::vector<AliasRequest> requests{{100, 1, 0, 1}, {300, 1, 2, 3}};
    const AliasPlan plan = plan_aliasing(requests);
    EXPECT_EQ(plan.offsets, (std::vector<uint64_t>{0, 0}));
    EXPECT_EQ(plan.heap_size, 300u);
    EXPECT_EQ(plan.unaliased_size, 400u);
}

TEST(framegraph_aliasing, OverlappingLifetimesDoNotOverlapInMemory) {
    // b overlaps a (at position 2) and c (at 3..4); a and c are disjoint.
    const std::vector<AliasRequest> requests{{256, 1, 0, 2}, {128, 1, 2, 3}, {256, 1, 3, 4}};
    const AliasPlan plan = plan_aliasing(requests);
    EXPECT_FALSE(ranges_overlap(plan, requests, 0, 1));
    EXPECT_FALSE(ranges_overlap(plan, requests, 1, 2));
    EXPECT_EQ(plan.offsets[0], plan.offsets[2]);  // a and c reuse the same memory
    EXPECT_EQ(plan.heap_size, 384u);
}

TEST(framegraph_aliasing, AlignmentIsRespected) {
    // Largest first: the 100-byte request at 0, the 64-byte one at the next multiple of 256.
    const std::vector<AliasRequest> requests{{64, 256, 0, 1}, {100, 1, 0, 1}};
    const AliasPlan plan = plan_aliasing(requests);
    EXPECT_EQ(plan.offsets[1], 0u);
    EXPECT_EQ(plan.offsets[0], 256u);
    EXPECT_EQ(plan.heap_size, 320u);
    // Without aliasing: 100 bytes, then 64 at the next multiple of 256.
    EXPECT_EQ(plan.unaliased_size, 320u);
}

TEST(framegraph_aliasing, UnaliasedSizeIsTheAlignedSum) {
    const std::vector<AliasRequest> requests{{4096, 4096, 0, 0}, {1000, 4096, 1, 1}, {10, 4096, 2, 2}};
    const AliasPlan plan = plan_aliasing(requests);
    EXPECT_EQ(plan.unaliased_size, 4096u + 4096u + 10u);
    EXPECT_EQ(plan.heap_size, 4096u);
}

TEST(framegraph_aliasing, PredecessorsAreEarlierOverlappingResources) {
    // a (0..1) and c (3..4) share memory; b (1..3) overlaps both in time, so not in memory.
    const std::vector<AliasRequest> requests{{512, 1, 0, 1}, {512, 1, 1, 3}, {512, 1, 3, 4}};
    const AliasPlan plan = plan_aliasing(requests);
    ASSERT_EQ(plan.offsets[0], plan.offsets[2]);
    EXPECT_TRUE(plan.predecessors[0].empty());
    EXPECT_TRUE(plan.predecessors[1].empty());
    EXPECT_EQ(plan.predecessors[2], (std::vector<uint32_t>{0}));
}

// Size of one 64x64 RGBA32F image: a multiple of the 4 KiB estimate alignment.
constexpr uint64_t kImageBytes = 64 * 64 * 16;

// make_a (compute) -> make_b (graphics: samples a, draws b) -> make_c (compute: samples b,
// writes c). a's last use (make_b) comes before c's first (make_c).
TEST(framegraph_aliasing, ChainOfThreeTransientsUsesTwoSlots) {
    FrameGraph graph;
    ImageHandle a, b, c;
    add_pass(graph, "make_a", PassKind::Compute,
             [&](PassBuilder& builder) { a = builder.write_storage(builder.create_image("a", small_image())); });
    add_pass(graph, "make_b", PassKind::Graphics, [&](PassBuilder& builder) {
        builder.sample(a);
        b = builder.color_attachment(builder.create_image("b", small_image()));
    });
    add_pass(graph, "make_c", PassKind::Compute, [&](PassBuilder& builder) {
        builder.sample(b);
        c = builder.write_storage(builder.create_image("c", small_image()));
    });
    graph.request_output(c);
    const CompiledGraph& compiled = graph.compile(64, 64);
    EXPECT_EQ(compiled.aliasing.unaliased_size, 3 * kImageBytes);
    EXPECT_EQ(compiled.aliasing.heap_size, 2 * kImageBytes);

    // c reuses a's memory, so its first barrier waits for every stage that touched a.
    const std::vector<BarrierRecord> barriers = barriers_of(graph);
    auto first_of_c = std::find_if(barriers.begin(), barriers.end(),
                                   [](const BarrierRecord& barrier) { return barrier.resource == "c"; });
    ASSERT_NE(first_of_c, barriers.end());
    EXPECT_EQ(*first_of_c, image_barrier("make_c", "c", {kCompute | kFragment, kStorageWrite, kUndefined},
                                         {kCompute, kStorageWrite, kGeneral}));
}

// exposes bug: FrameGraph::apply_aliasing (frame_graph.cpp, `timeline.initial.access =
// access.state.access`) keeps only the last predecessor's write access. Here "big"
// reuses the memory of both "storage" (SHADER_STORAGE_WRITE, never read, so never made
// available by another barrier) and "copied" (TRANSFER_WRITE); its first barrier must
// name both writes, but gets only TRANSFER_WRITE.
TEST(framegraph_aliasing, ReuseWaitsForEveryPredecessorsWrites) {
    FrameGraph graph;
    add_pass(graph, "fill", PassKind::Compute, [&](PassBuilder& builder) {
        builder.side_effect();
        (void)builder.write_storage(builder.create_buffer("storage", {4096}));
        (void)builder.copy_destination(builder.create_buffer("copied", {4096}));
    });
    add_pass(graph, "overwrite", PassKind::Compute, [&](PassBuilder& builder) {
        graph.request_output(builder.write_storage(builder.create_buffer("big", {8192})));
    });
    const CompiledGraph& compiled = graph.compile(64, 64);
    EXPECT_EQ(compiled.aliasing.heap_size, 8192u);
    const std::vector<BarrierRecord> expected{
        buffer_barrier("overwrite", "big", {kCompute | kCopy, kStorageWrite | kTransferWrite},
                       {kCompute, kStorageWrite}),
    };
    EXPECT_EQ(barriers_of(graph), expected);
}

}  // namespace
}  // namespace vkw::fg::test
