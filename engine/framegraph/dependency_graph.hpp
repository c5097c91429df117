// A generic directed acyclic graph of named nodes with reference-count culling and a
// stable topological order. The frame graph builds one from passes and resource
// versions; the culling and ordering logic lives here alone so that it can be tested
// on bare nodes, without resources or Vulkan.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace vkw::fg {

class DependencyGraph {
public:
    using NodeId = uint32_t;

    NodeId add_node(std::string name);
    // `from` must happen before `to`; `to` consumes what `from` produces.
    void add_edge(NodeId from, NodeId to);
    // A pinned node is never culled and keeps everything it depends on alive
    // (a requested output, or a pass with side effects).
    void pin(NodeId node);
    // Removes a node before culling as if it did not exist: its producers lose a consumer.
    // Used for passes whose effect the frame does not need.
    void force_cull(NodeId node);

    // Reference-count culling: a node lives if it is pinned or if a living node
    // consumes it. Returns the number of culled nodes.
    size_t cull();
    bool is_culled(NodeId node) const { return nodes_[node].culled; }

    // Living nodes in a topological order; among ready nodes the lowest id comes
    // first, so the order is the insertion order whenever that order is valid.
    // Throws InternalError naming the nodes of a cycle.
    std::vector<NodeId> topological_order() const;

    const std::string& name(NodeId node) const { return nodes_[node].name; }
    size_t size() const { return nodes_.size(); }
    const std::vector<NodeId>& consumers(NodeId node) const { return nodes_[node].consumers; }
    const std::vector<NodeId>& producers(NodeId node) const { return nodes_[node].producers; }

private:
    struct Node {
        std::string name;
        std::vector<NodeId> producers;
        std::vector<NodeId> consumers;
        bool pinned = false;
        bool forced_cull = false;
        bool culled = false;
    };
    std::vector<Node> nodes_;
};

}  // namespace vkw::fg
