// The scene's receiver meshes on the device: one vertex buffer (position, normal) and
// one index buffer for all of them, filled once from the scene's world-space meshes
// and imported into each frame's graph. Owned by the renderer; alive while frames that
// imported it execute.
#pragma once

#include "engine/framegraph/frame_graph.hpp"
#include "engine/scene/scene.hpp"
#include "engine/vk/resources.hpp"

#include <glm/glm.hpp>

#include <vector>

namespace vkw {
class Context;
}

namespace vkw::passes {

struct ReceiverDraw {
    uint32_t first_index, index_count;
    int32_t vertex_offset;
    glm::vec3 albedo;
};

class ReceiverMeshes {
public:
    ReceiverMeshes(const Context& context, const std::vector<Receiver>& receivers);

    bool empty() const { return draws_.empty(); }
    const std::vector<ReceiverDraw>& draws() const { return draws_; }
    // The world-space box around every vertex (meaningless when empty()).
    const glm::dvec3& bounds_lo() const { return bounds_lo_; }
    const glm::dvec3& bounds_hi() const { return bounds_hi_; }
    // Imported with the state the constructor's host writes left them in; read only.
    fg::BufferHandle import_vertices(fg::FrameGraph& graph) const;
    fg::BufferHandle import_indices(fg::FrameGraph& graph) const;

private:
    Buffer vertices_, indices_;
    std::vector<ReceiverDraw> draws_;
    glm::dvec3 bounds_lo_{0.0}, bounds_hi_{0.0};
};

}  // namespace vkw::passes
