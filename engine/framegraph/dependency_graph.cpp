#include "engine/framegraph/dependency_graph.hpp"

#include "engine/core/errors.hpp"

#include <queue>

namespace vkw::fg {

DependencyGraph::NodeId DependencyGraph::add_node(std::string name) {
    nodes_.push_back(Node{std::move(name)});
    return static_cast<NodeId>(nodes_.size() - 1);
}

void DependencyGraph::add_edge(NodeId from, NodeId to) {
    nodes_[from].consumers.push_back(to);
    nodes_[to].producers.push_back(from);
}

void DependencyGraph::pin(NodeId node) { nodes_[node].pinned = true; }

void DependencyGraph::force_cull(NodeId node) { nodes_[node].forced_cull = true; }

size_t DependencyGraph::cull() {
    // Each node's reference count is the number of its consumers that may still live.
    std::vector<uint32_t> references(nodes_.size(), 0);
    std::vector<NodeId> unreferenced;
    for (NodeId id = 0; id < nodes_.size(); ++id) {
        Node& node = nodes_[id];
        node.culled = false;
        for (NodeId consumer : node.consumers) {
            if (!nodes_[consumer].forced_cull) ++references[id];
        }
    }
    for (NodeId id = 0; id < nodes_.size(); ++id) {
        const Node& node = nodes_[id];
        if (node.forced_cull || (references[id] == 0 && !node.pinned)) unreferenced.push_back(id);
    }
    // Culling a node releases one reference on each of its producers.
    size_t culled = 0;
    while (!unreferenced.empty()) {
        const NodeId id = unreferenced.back();
        unreferenced.pop_back();
        Node& node = nodes_[id];
        if (node.culled) continue;
        node.culled = true;
        ++culled;
        if (node.forced_cull) continue;  // its references were never counted
        for (NodeId producer : node.producers) {
            if (--references[producer] == 0 && !nodes_[producer].pinned) unreferenced.push_back(producer);
        }
    }
    return culled;
}

std::vector<DependencyGraph::NodeId> DependencyGraph::topological_order() const {
    std::vector<uint32_t> pending(nodes_.size(), 0);
    size_t living = 0;
    for (NodeId id = 0; id < nodes_.size(); ++id) {
        if (nodes_[id].culled) continue;
        ++living;
        for (NodeId producer : nodes_[id].producers) {
            if (!nodes_[producer].culled) ++pending[id];
        }
    }
    std::priority_queue<NodeId, std::vector<NodeId>, std::greater<>> ready;
    for (NodeId id = 0; id < nodes_.size(); ++id) {
        if (!nodes_[id].culled && pending[id] == 0) ready.push(id);
    }
    std::vector<NodeId> order;
    order.reserve(living);
    while (!ready.empty()) {
        const NodeId id = ready.top();
        ready.pop();
        order.push_back(id);
        for (NodeId consumer : nodes_[id].consumers) {
            if (!nodes_[consumer].culled && --pending[consumer] == 0) ready.push(consumer);
        }
    }
    if (order.size() != living) {
        std::string cycle;
        for (NodeId id = 0; id < nodes_.size(); ++id) {
            if (!nodes_[id].culled && pending[id] > 0) cycle += (cycle.empty() ? "'" : ", '") + nodes_[id].name + "'";
        }
        throw InternalError("frame graph has a cycle through " + cycle);
    }
    return order;
}

}  // namespace vkw::fg
