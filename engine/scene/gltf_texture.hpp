// Base colour textures of a glTF file: which images the materials sample, their decoding (Debian's
// stb_image, through tinygltf's image callback, within the limits below), and a material's
// baseColorTexture as a MeshTexture with its texture coordinate set and KHR_texture_transform.
// Only gltf_mesh.cpp uses this; like it, this is where tinygltf's types stay.
#pragma once

#include <cstdint>
#include <map>
#include <memory>
#include <set>
#include <string>

#include <glm/glm.hpp>
#include <nlohmann/json_fwd.hpp>

#include "engine/scene/mesh.hpp"

namespace tinygltf {
struct Image;
struct Model;
struct TextureInfo;
}  // namespace tinygltf

namespace vkw {

// Per side of one image, and decoded bytes (4 per texel) of all the images one file uses: an
// 8192^2 texture is 256 MiB decoded, the real-time copy a third more for its mip levels.
inline constexpr uint32_t kMaxTextureSide = 8192;
inline constexpr uint64_t kMaxTextureBytes = uint64_t(256) << 20;

// The images that some material's pbrMetallicRoughness.baseColorTexture samples (through
// textures[i].source), from the file's JSON: the others (normal maps and the like) are not decoded.
std::set<int> base_color_images(const nlohmann::json& document);

// Decodes the wanted images to 8-bit RGBA as tinygltf hands over their bytes (an external file,
// a data URI or a .glb's bufferView) and skips the others. A refusal (not PNG, JPEG, BMP, GIF, TGA
// or another format stb_image reads; beyond the limits) is kept and reported after tinygltf returns,
// as one line naming the image.
class GltfImageDecoder {
public:
    explicit GltfImageDecoder(std::set<int> wanted) : wanted_(std::move(wanted)) {}

    // tinygltf's LoadImageDataFunction; `user` is the decoder.
    static bool decode(tinygltf::Image* image, int index, std::string* error, std::string* warning, int, int,
                       const unsigned char* bytes, int size, void* user);
    const std::string& failure() const { return failure_; }

private:
    bool decode_image(tinygltf::Image& image, int index, const unsigned char* bytes, int size);
    std::set<int> wanted_;
    uint64_t decoded_bytes_ = 0;
    std::string failure_;
};

// A material's base colour texture: the texture coordinate set it reads and the affine map from
// that set's coordinates to the image's (identity without KHR_texture_transform).
struct UvMapping {
    int set = 0;
    glm::dmat3 transform{1.0};
};
UvMapping uv_mapping(const tinygltf::TextureInfo& info);

// textures[index] of the model as a MeshTexture (its image decoded, its sampler's wrap and filter
// modes), each image shared between the textures that use it through `images`. Throws UserError
// (without the file's name; the caller adds it) for an index, source or sampler that does not exist.
MeshTexture mesh_texture(const tinygltf::Model& model, int index,
                         std::map<int, std::shared_ptr<const TextureImage>>& images);

}  // namespace vkw
