// A triangle mesh as the renderers consume it: the one geometry every receiver becomes, whether
// built in (builtin_meshes.hpp) or loaded from glTF (gltf_mesh.hpp). Positions and normals are
// single precision (what the GPU reads; the reference renderer widens them); bounds are exact
// over the stored positions. Triangles are counter-clockwise seen from the side the normals
// point to (glTF's front face).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include <glm/glm.hpp>

namespace vkw {

// Triangles that share one material: indices [first_index, first_index + index_count) of the
// mesh, with their base colour (linear RGB, each in [0, 1]).
struct MeshPart {
    uint32_t first_index = 0;
    uint32_t index_count = 0;
    glm::dvec3 base_color{1.0};
};

struct Mesh {
    std::vector<glm::vec3> positions;
    std::vector<glm::vec3> normals;  // unit, one per position
    std::vector<glm::vec2> uvs;      // one per position, or empty when the source has none
    std::vector<uint32_t> indices;   // three per triangle
    glm::dvec3 bounds_min{0.0};
    glm::dvec3 bounds_max{0.0};
    // A glTF file's materials: one part per primitive, in index order, covering every index;
    // empty for the built-in shapes (the receiver's albedo colours them whole).
    std::vector<MeshPart> parts;
    // The base colour texture: a path (an external image, resolved against the glTF file's
    // folder) or "<gltf path>#images[i]" for an image embedded in the glTF; empty for none.
    std::string base_color_texture;
    // What the file asks for that the renderers leave out, one sentence each (skipped points and
    // lines, skins, morph targets, material features): the commands print them as warnings.
    std::vector<std::string> warnings;
};

// Recomputes bounds_min and bounds_max from the positions (both zero for an empty mesh).
void update_bounds(Mesh& mesh);

// Applies `object_to_world` to the positions and its inverse transpose to the normals
// (renormalised), then updates the bounds. The matrix must be invertible.
void transform_mesh(Mesh& mesh, const glm::dmat4& object_to_world);

}  // namespace vkw
