// The scene's receiver meshes on the device: one vertex buffer (position, normal, base colour
// texture coordinates, vertex colour) and one index buffer for all of them, filled once from the
// scene's world-space meshes and imported into each frame's graph, and their base colour textures.
// Owned by the renderer; alive while frames that imported it execute.
#pragma once

#include "engine/framegraph/frame_graph.hpp"
#include "engine/scene/scene.hpp"
#include "engine/vk/resources.hpp"
#include "passes/receivers/receiver_textures.hpp"

#include <glm/glm.hpp>

#include <memory>
#include <vector>

namespace vkw {
class Context;
}

namespace vkw::passes {

// Bytes per vertex of the meshes' vertex buffer (its layout: use_receiver_mesh_vertices).
inline constexpr uint32_t kReceiverVertexBytes = 12 * sizeof(float);

struct ReceiverDraw {
    uint32_t first_index, index_count;
    int32_t vertex_offset;
    glm::vec3 albedo;
    int32_t texture;     // ReceiverTextures' index; -1: untextured (white)
    float alpha;         // the base colour factor's alpha
    float alpha_cutoff;  // a cutout's threshold (MeshPart::alpha_cutoff); negative: opaque
};

class ReceiverMeshes {
public:
    ReceiverMeshes(Context& context, const std::vector<Receiver>& receivers);

    bool empty() const { return draws_.empty(); }
    const std::vector<ReceiverDraw>& draws() const { return draws_; }
    // Whether some part's base colour varies over it (a texture or vertex colours): only then do
    // the meshes' draws sample a texture (receiver_mesh_pipeline); a flat albedo per draw otherwise.
    bool varied_base_color() const { return textures_ != nullptr; }
    // Whether some part is a cutout (then its base colour varies too).
    bool has_cutouts() const { return has_cutouts_; }
    const ReceiverTextures& textures() const { return *textures_; }
    // The world-space box around every vertex (meaningless when empty()).
    const glm::dvec3& bounds_lo() const { return bounds_lo_; }
    const glm::dvec3& bounds_hi() const { return bounds_hi_; }
    // Imported with the state the constructor's host writes left them in; read only.
    fg::BufferHandle import_vertices(fg::FrameGraph& graph) const;
    fg::BufferHandle import_indices(fg::FrameGraph& graph) const;

private:
    Buffer vertices_, indices_;
    std::vector<ReceiverDraw> draws_;
    std::unique_ptr<ReceiverTextures> textures_;  // null unless varied_base_color()
    bool has_cutouts_ = false;
    glm::dvec3 bounds_lo_{0.0}, bounds_hi_{0.0};
};

}  // namespace vkw::passes
