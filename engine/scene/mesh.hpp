// A triangle mesh as the renderers consume it: the one geometry every receiver becomes, whether
// built in (builtin_meshes.hpp) or loaded from glTF (gltf_mesh.hpp). Positions and normals are
// single precision (what the GPU reads; the reference renderer widens them); bounds are exact
// over the stored positions. Triangles are counter-clockwise seen from the side the normals
// point to (glTF's front face).
#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include <glm/glm.hpp>

namespace vkw {

// A decoded base colour image: 8-bit RGBA, colour sRGB-encoded and alpha linear (as glTF stores
// it), rows from the top: texture coordinate (0, 0) is the first texel's outer corner.
struct TextureImage {
    uint32_t width = 0;
    uint32_t height = 0;
    std::vector<uint8_t> rgba;  // 4 * width * height
};

// glTF's wrap modes (sampler.wrapS and wrapT).
enum class TextureWrap : uint8_t { Repeat, ClampToEdge, MirroredRepeat };

// A base colour texture as a material uses it: the image and its glTF sampler. The filters are
// what the real-time renderer honours (the reference samples the base level bilinearly always).
struct MeshTexture {
    std::shared_ptr<const TextureImage> image;
    TextureWrap wrap_u = TextureWrap::Repeat;
    TextureWrap wrap_v = TextureWrap::Repeat;
    bool magnify_linear = true;  // magFilter LINEAR (or unset), else NEAREST
    bool minify_linear = true;   // minFilter *LINEAR* within a level (or unset)
    bool mipmaps = true;         // minFilter *_MIPMAP_* (or unset); NEAREST and LINEAR use the base level alone
    bool mipmap_linear = true;   // between levels: *_MIPMAP_LINEAR (or unset)
};

// Triangles that share one material: indices [first_index, first_index + index_count) of the
// mesh, with their base colour factor (linear RGB, each in [0, 1]) and, when texture >= 0,
// Mesh::textures[texture] multiplied in at each point's texture coordinates. A cutout (glTF's
// alphaMode MASK) leaves out every point whose alpha, the factor's times the texture's times the
// vertex colour's, is below alpha_cutoff: light and views pass through it.
struct MeshPart {
    uint32_t first_index = 0;
    uint32_t index_count = 0;
    glm::dvec3 base_color{1.0};
    int32_t texture = -1;
    double alpha = 1.0;          // the base colour factor's alpha
    double alpha_cutoff = -1.0;  // negative: opaque (every point kept)
};

struct Mesh {
    std::vector<glm::vec3> positions;
    std::vector<glm::vec3> normals;  // unit, one per position
    // One per position, or empty when no part is textured: each part's base colour texture
    // coordinates (its TEXCOORD_n, KHR_texture_transform applied).
    std::vector<glm::vec2> uvs;
    // glTF's COLOR_0 (linear RGB and alpha, multiplied into the base colour): one per position, or
    // empty for opaque white.
    std::vector<glm::vec4> colors;
    std::vector<uint32_t> indices;  // three per triangle
    glm::dvec3 bounds_min{0.0};
    glm::dvec3 bounds_max{0.0};
    // A glTF file's materials: one part per primitive, in index order, covering every index;
    // empty for the built-in shapes (the receiver's albedo colours them whole).
    std::vector<MeshPart> parts;
    std::vector<MeshTexture> textures;  // what parts' `texture` indices name
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
