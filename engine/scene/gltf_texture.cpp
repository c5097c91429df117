// glTF base colour textures (see gltf_texture.hpp). Debian's libstb is compiled: no
// STB_IMAGE_IMPLEMENTATION here.
#include "engine/scene/gltf_texture.hpp"

#include <tiny_gltf.h>

#include <cmath>
#include <string>

#include <stb_image.h>
#include <nlohmann/json.hpp>

#include "engine/core/errors.hpp"

namespace vkw {
namespace {

TextureWrap wrap_mode(int mode, const std::string& where) {
    switch (mode) {
        case TINYGLTF_TEXTURE_WRAP_REPEAT: return TextureWrap::Repeat;
        case TINYGLTF_TEXTURE_WRAP_CLAMP_TO_EDGE: return TextureWrap::ClampToEdge;
        case TINYGLTF_TEXTURE_WRAP_MIRRORED_REPEAT: return TextureWrap::MirroredRepeat;
        default:
            throw UserError(where + " " + std::to_string(mode) +
                            " is not a glTF wrap mode (accepted: 10497 REPEAT, 33071 CLAMP_TO_EDGE, "
                            "33648 MIRRORED_REPEAT)");
    }
}

double number_or(const tinygltf::Value& object, const char* key, int index, double fallback) {
    if (!object.Has(key)) return fallback;
    const tinygltf::Value& member = object.Get(key);
    if (index >= 0 && !(member.IsArray() && std::size_t(index) < member.ArrayLen())) return fallback;
    const tinygltf::Value& value = index < 0 ? member : member.Get(index);
    return value.IsNumber() ? value.GetNumberAsDouble() : fallback;
}

}  // namespace

std::set<int> base_color_images(const nlohmann::json& document) {
    std::set<int> images;
    const auto materials = document.find("materials");
    const auto textures = document.find("textures");
    if (materials == document.end() || !materials->is_array() || textures == document.end() || !textures->is_array()) {
        return images;
    }
    for (const nlohmann::json& material : *materials) {
        const nlohmann::json* info = nullptr;
        if (material.is_object() && material.contains("pbrMetallicRoughness")) {
            const nlohmann::json& pbr = material["pbrMetallicRoughness"];
            if (pbr.is_object() && pbr.contains("baseColorTexture")) info = &pbr["baseColorTexture"];
        }
        if (!info || !info->is_object() || !info->contains("index") || !(*info)["index"].is_number_unsigned()) continue;
        const auto texture = (*info)["index"].get<std::size_t>();
        if (texture >= textures->size() || !(*textures)[texture].is_object()) continue;
        const nlohmann::json& entry = (*textures)[texture];
        if (entry.contains("source") && entry["source"].is_number_unsigned()) images.insert(entry["source"].get<int>());
    }
    return images;
}

bool GltfImageDecoder::decode(tinygltf::Image* image, int index, std::string* error, std::string*, int, int,
                              const unsigned char* bytes, int size, void* user) {
    auto& decoder = *static_cast<GltfImageDecoder*>(user);
    if (decoder.decode_image(*image, index, bytes, size)) return true;
    if (error) *error = decoder.failure_;
    return false;
}

bool GltfImageDecoder::decode_image(tinygltf::Image& image, int index, const unsigned char* bytes, int size) {
    if (!wanted_.contains(index)) return true;  // not a base colour: left empty
    const std::string name = "images[" + std::to_string(index) + "]";
    int width = 0, height = 0, channels = 0;
    // The header first, so that no declared size is allocated before it is checked.
    if (!stbi_info_from_memory(bytes, size, &width, &height, &channels)) {
        failure_ = name + ": not an image stb_image decodes (PNG, JPEG, BMP, GIF, TGA, PSD, HDR, PIC, PNM): " +
                   stbi_failure_reason();
        return false;
    }
    if (width <= 0 || height <= 0 || uint32_t(width) > kMaxTextureSide || uint32_t(height) > kMaxTextureSide) {
        failure_ = name + ": " + std::to_string(width) + " x " + std::to_string(height) + " texels (accepted: 1 to " +
                   std::to_string(kMaxTextureSide) + " per side)";
        return false;
    }
    const uint64_t texture_bytes = 4 * uint64_t(width) * uint64_t(height);
    if (decoded_bytes_ + texture_bytes > kMaxTextureBytes) {
        failure_ = name + ": the base colour images decode to more than " + std::to_string(kMaxTextureBytes >> 20) +
                   " MiB together (accepted: at most that)";
        return false;
    }
    // 16-bit PNGs come down to 8 bits per channel: the base colour is an 8-bit sRGB quantity here.
    stbi_uc* texels = stbi_load_from_memory(bytes, size, &width, &height, &channels, 4);
    if (!texels) {
        failure_ = name + ": stb_image could not decode it: " + std::string(stbi_failure_reason());
        return false;
    }
    decoded_bytes_ += texture_bytes;
    image.width = width;
    image.height = height;
    image.component = 4;
    image.bits = 8;
    image.pixel_type = TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE;
    image.image.assign(texels, texels + texture_bytes);
    stbi_image_free(texels);
    return true;
}

UvMapping uv_mapping(const tinygltf::TextureInfo& info) {
    UvMapping mapping;
    mapping.set = info.texCoord;
    const auto extension = info.extensions.find("KHR_texture_transform");
    if (extension == info.extensions.end() || !extension->second.IsObject()) return mapping;
    const tinygltf::Value& transform = extension->second;
    // The extension's matrix: translation * rotation * scale, the rotation's columns (cos, sin) and
    // (-sin, cos) as the extension's GLSL writes them; column-major, as glm.
    const double rotation = number_or(transform, "rotation", -1, 0.0);
    const glm::dvec2 offset(number_or(transform, "offset", 0, 0.0), number_or(transform, "offset", 1, 0.0));
    const glm::dvec2 scale(number_or(transform, "scale", 0, 1.0), number_or(transform, "scale", 1, 1.0));
    const double c = std::cos(rotation), s = std::sin(rotation);
    mapping.transform = glm::dmat3(glm::dvec3(c * scale.x, s * scale.x, 0.0),
                                   glm::dvec3(-s * scale.y, c * scale.y, 0.0), glm::dvec3(offset, 1.0));
    if (transform.Has("texCoord") && transform.Get("texCoord").IsNumber()) {
        mapping.set = transform.Get("texCoord").GetNumberAsInt();
    }
    return mapping;
}

MeshTexture mesh_texture(const tinygltf::Model& model, int index,
                         std::map<int, std::shared_ptr<const TextureImage>>& images) {
    const std::string name = "textures[" + std::to_string(index) + "]";
    if (index < 0 || std::size_t(index) >= model.textures.size()) throw UserError("no " + name);
    const tinygltf::Texture& texture = model.textures[std::size_t(index)];
    const int source = texture.source;
    if (source < 0 || std::size_t(source) >= model.images.size()) throw UserError(name + " has no image");
    MeshTexture result;
    std::shared_ptr<const TextureImage>& image = images[source];
    if (!image) {
        const tinygltf::Image& decoded = model.images[std::size_t(source)];
        if (decoded.image.empty()) throw UserError("images[" + std::to_string(source) + "] was not decoded");
        auto texels = std::make_shared<TextureImage>();
        texels->width = uint32_t(decoded.width);
        texels->height = uint32_t(decoded.height);
        texels->rgba = decoded.image;
        image = std::move(texels);
    }
    result.image = image;
    if (texture.sampler < 0) return result;  // glTF's default: repeat, filters the renderer's choice
    if (std::size_t(texture.sampler) >= model.samplers.size()) {
        throw UserError(name + ": no samplers[" + std::to_string(texture.sampler) + "]");
    }
    const tinygltf::Sampler& sampler = model.samplers[std::size_t(texture.sampler)];
    const std::string sampler_name = "samplers[" + std::to_string(texture.sampler) + "]";
    result.wrap_u = wrap_mode(sampler.wrapS, sampler_name + ".wrapS");
    result.wrap_v = wrap_mode(sampler.wrapT, sampler_name + ".wrapT");
    result.magnify_linear = sampler.magFilter != TINYGLTF_TEXTURE_FILTER_NEAREST;
    switch (sampler.minFilter) {
        case TINYGLTF_TEXTURE_FILTER_NEAREST: result.minify_linear = result.mipmaps = false; break;
        case TINYGLTF_TEXTURE_FILTER_LINEAR: result.mipmaps = false; break;
        case TINYGLTF_TEXTURE_FILTER_NEAREST_MIPMAP_NEAREST: result.minify_linear = result.mipmap_linear = false; break;
        case TINYGLTF_TEXTURE_FILTER_LINEAR_MIPMAP_NEAREST: result.mipmap_linear = false; break;
        case TINYGLTF_TEXTURE_FILTER_NEAREST_MIPMAP_LINEAR: result.minify_linear = false; break;
        default: break;  // LINEAR_MIPMAP_LINEAR, or unset: trilinear
    }
    return result;
}

}  // namespace vkw
