#include "passes/receivers/receiver_meshes.hpp"

#include "engine/vk/context.hpp"

#include <cstring>

namespace vkw::passes {
namespace {

// The vertex layout of receivers/mesh.vert (use_receiver_mesh_vertices).
struct Vertex {
    glm::vec3 position;
    glm::vec3 normal;
    glm::vec2 uv;
    glm::vec4 color;
};

static_assert(sizeof(Vertex) == kReceiverVertexBytes);

fg::AccessState host_written() { return {VK_PIPELINE_STAGE_2_HOST_BIT, VK_ACCESS_2_HOST_WRITE_BIT}; }

}  // namespace

ReceiverMeshes::ReceiverMeshes(Context& context, const std::vector<Receiver>& receivers) {
    std::vector<Vertex> vertices;
    std::vector<uint32_t> indices;
    std::vector<const MeshTexture*> textures;
    bool varied = false;
    for (const Receiver& receiver : receivers) {
        const Mesh& mesh = receiver.mesh;
        if (mesh.indices.empty()) continue;
        // One draw per part: each with its own albedo and texture, the mesh's vertices shared.
        const auto first_texture = int32_t(textures.size());
        for (const MeshTexture& texture : mesh.textures) textures.push_back(&texture);
        varied = varied || !mesh.colors.empty();
        for (const MeshPart& part : receiver_albedo_parts(receiver)) {
            has_cutouts_ = has_cutouts_ || part.alpha_cutoff >= 0.0;
            varied = varied || part.texture >= 0 || part.alpha_cutoff >= 0.0;
            draws_.push_back({static_cast<uint32_t>(indices.size()) + part.first_index, part.index_count,
                              static_cast<int32_t>(vertices.size()), glm::vec3(part.base_color),
                              part.texture < 0 ? -1 : first_texture + part.texture, float(part.alpha),
                              float(part.alpha_cutoff)});
        }
        for (size_t i = 0; i < mesh.positions.size(); ++i) {
            vertices.push_back({mesh.positions[i], mesh.normals[i], mesh.uvs.empty() ? glm::vec2(0.0f) : mesh.uvs[i],
                                mesh.colors.empty() ? glm::vec4(1.0f) : mesh.colors[i]});
        }
        indices.insert(indices.end(), mesh.indices.begin(), mesh.indices.end());
    }
    if (varied) textures_ = std::make_unique<ReceiverTextures>(context, textures);
    if (draws_.empty()) return;
    bounds_lo_ = bounds_hi_ = glm::dvec3(vertices.front().position);
    for (const Vertex& vertex : vertices) {
        bounds_lo_ = glm::min(bounds_lo_, glm::dvec3(vertex.position));
        bounds_hi_ = glm::max(bounds_hi_, glm::dvec3(vertex.position));
    }
    // Host-visible buffers written once: on lavapipe all memory is host-visible anyway,
    // and on a GPU the vertex fetch from host memory is acceptable for receivers.
    vertices_ = Buffer(context, {vertices.size() * sizeof(Vertex), VK_BUFFER_USAGE_VERTEX_BUFFER_BIT, true},
                       "receiver vertices");
    std::memcpy(vertices_.mapped(), vertices.data(), vertices.size() * sizeof(Vertex));
    indices_ = Buffer(context, {indices.size() * sizeof(uint32_t), VK_BUFFER_USAGE_INDEX_BUFFER_BIT, true},
                      "receiver indices");
    std::memcpy(indices_.mapped(), indices.data(), indices.size() * sizeof(uint32_t));
}

fg::BufferHandle ReceiverMeshes::import_vertices(fg::FrameGraph& graph) const {
    return graph.import_buffer("receiver vertices", {vertices_.handle(), vertices_.size(), host_written()});
}

fg::BufferHandle ReceiverMeshes::import_indices(fg::FrameGraph& graph) const {
    return graph.import_buffer("receiver indices", {indices_.handle(), indices_.size(), host_written()});
}

}  // namespace vkw::passes
