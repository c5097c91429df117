// DependencyGraph on bare nodes: reference-count culling (pins, forced culls, shared
// producers), the stable topological order and the cycle error.
#include "tests/framegraph/framegraph_test_support.hpp"

#include "engine/framegraph/dependency_graph.hpp"

namespace vkw::fg::test {
namespace {

using NodeId = DependencyGraph::NodeId;

// Adds nodes named by `names` and the edges `from -> to` (indices into `names`).
DependencyGraph make_graph(std::initializer_list<const char*> names,
                           std::initializer_list<std::pair<NodeId, NodeId>> edges) {
    DependencyGraph graph;
    for (const char* name : names) graph.add_node(name);
    for (auto [from, to] : edges) graph.add_edge(from, to);
    return graph;
}

std::vector<std::string> names_of(const DependencyGraph& graph, const std::vector<NodeId>& nodes) {
    std::vector<std::string> names;
    for (NodeId node : nodes) names.push_back(graph.name(node));
    return names;
}

std::vector<std::string> living(const DependencyGraph& graph) { return names_of(graph, graph.topological_order()); }

TEST(framegraph_dependency_graph, ChainIntoUnpinnedSinkIsAllCulled) {
    DependencyGraph graph = make_graph({"a", "b", "c", "sink"}, {{0, 1}, {1, 2}, {2, 3}});
    EXPECT_EQ(graph.cull(), 4u);
    for (NodeId node = 0; node < graph.size(); ++node) EXPECT_TRUE(graph.is_culled(node)) << graph.name(node);
    EXPECT_TRUE(graph.topological_order().empty());
}

TEST(framegraph_dependency_graph, PinnedSinkKeepsItsChain) {
    DependencyGraph graph = make_graph({"a", "b", "c", "sink"}, {{0, 1}, {1, 2}, {2, 3}});
    graph.pin(3);
    EXPECT_EQ(graph.cull(), 0u);
    EXPECT_EQ(living(graph), (std::vector<std::string>{"a", "b", "c", "sink"}));
}

TEST(framegraph_dependency_graph, ProducerWithOneCulledConsumerLives) {
    // a feeds a pinned sink and an unpinned one: only the unpinned branch goes.
    DependencyGraph graph = make_graph({"a", "kept", "dropped"}, {{0, 1}, {0, 2}});
    graph.pin(1);
    EXPECT_EQ(graph.cull(), 1u);
    EXPECT_TRUE(graph.is_culled(2));
    EXPECT_EQ(living(graph), (std::vector<std::string>{"a", "kept"}));
}

TEST(framegraph_dependency_graph, ForceCullRemovesNodeThenItsUnusedProducers) {
    // only_for_b feeds only the forced node; shared also feeds a pinned node.
    DependencyGraph graph = make_graph({"only_for_b", "shared", "b", "pinned"}, {{0, 2}, {1, 2}, {1, 3}});
    graph.pin(2);  // forcing wins over pinning
    graph.pin(3);
    graph.force_cull(2);
    EXPECT_EQ(graph.cull(), 2u);
    EXPECT_TRUE(graph.is_culled(0));
    EXPECT_TRUE(graph.is_culled(2));
    EXPECT_EQ(living(graph), (std::vector<std::string>{"shared", "pinned"}));
}

TEST(framegraph_dependency_graph, ForceCullPropagatesThroughAChain) {
    DependencyGraph graph = make_graph({"a", "b", "forced"}, {{0, 1}, {1, 2}});
    graph.pin(2);
    graph.force_cull(2);
    EXPECT_EQ(graph.cull(), 3u);
}

TEST(framegraph_dependency_graph, OrderIsInsertionOrderWhenValid) {
    // A diamond plus an independent node, every edge pointing to a later node.
    DependencyGraph graph = make_graph({"a", "b", "c", "lone", "d"}, {{0, 1}, {0, 2}, {1, 4}, {2, 4}});
    graph.pin(3);
    graph.pin(4);
    graph.cull();
    EXPECT_EQ(graph.topological_order(), (std::vector<NodeId>{0, 1, 2, 3, 4}));
}

TEST(framegraph_dependency_graph, LowestReadyIdComesFirst) {
    // "late" (id 0) depends on "first" (id 1); "other" (id 2) is ready from the start.
    // Once "first" is done, "late" is ready and beats "other" by its lower id.
    DependencyGraph graph = make_graph({"late", "first", "other"}, {{1, 0}});
    graph.pin(0);
    graph.pin(2);
    graph.cull();
    EXPECT_EQ(living(graph), (std::vector<std::string>{"first", "late", "other"}));
}

TEST(framegraph_dependency_graph, CulledNodesAreLeftOutOfTheOrder) {
    DependencyGraph graph = make_graph({"a", "unused", "b"}, {{0, 1}, {0, 2}});
    graph.pin(2);
    graph.cull();
    EXPECT_EQ(living(graph), (std::vector<std::string>{"a", "b"}));
}

TEST(framegraph_dependency_graph, CycleErrorNamesItsNodes) {
    // before -> x -> y -> x: the cycle is x, y.
    DependencyGraph graph = make_graph({"before", "x", "y"}, {{0, 1}, {1, 2}, {2, 1}});
    graph.pin(2);
    graph.cull();
    const std::string message = internal_error_of([&] { graph.topological_order(); });
    expect_contains(message, {"cycle", "'x'", "'y'"});
    EXPECT_EQ(message.find("'before'"), std::string::npos) << message;
}

}  // namespace
}  // namespace vkw::fg::test
