// A textured glTF square the tests write themselves: [-1, 1]^2 in y = 0 facing +y (normals given),
// with texture coordinates u = (x + 1) / 2, v = (z + 1) / 2 (so the image's first row lies along
// z = -1), one material whose base colour texture is an embedded PNG of the given texels, and optionally
// COLOR_0, a sampler and KHR_texture_transform.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include <stb_image_write.h>

#include "tests/scene/gltf_test_files.hpp"

namespace vkw::test {

struct TexturedSquare {
    uint32_t width = 2, height = 2;
    std::vector<uint8_t> rgba = {255, 0, 0, 255, 0, 255, 0, 255, 0, 0, 255, 255, 255, 255, 255, 255};
    std::string sampler;             // a samplers[0] object; empty: none
    std::string texture_info_extra;  // more members of baseColorTexture, each followed by a comma
    std::string base_color_factor = "[1, 1, 1, 1]";
    std::string material_extra;   // more members of the material, each followed by a comma
    std::vector<uint8_t> colors;  // COLOR_0 as normalised unsigned bytes, RGBA per vertex; empty: none
    std::string top_extra;        // more top-level members, each followed by a comma
};

inline std::vector<unsigned char> png_bytes(uint32_t width, uint32_t height, const std::vector<uint8_t>& rgba) {
    std::vector<unsigned char> png;
    const auto append = [](void* context, void* data, int size) {
        auto* out = static_cast<std::vector<unsigned char>*>(context);
        out->insert(out->end(), static_cast<unsigned char*>(data), static_cast<unsigned char*>(data) + size);
    };
    stbi_write_png_to_func(append, &png, int(width), int(height), 4, rgba.data(), int(width * 4));
    return png;
}

inline std::string textured_square_text(const TexturedSquare& square) {
    std::vector<unsigned char> data;
    append_bytes(data, std::vector<float>{-1, 0, -1, -1, 0, 1, 1, 0, 1, 1, 0, -1});  // positions
    append_bytes(data, std::vector<float>{0, 0, 0, 1, 1, 1, 1, 0});                  // TEXCOORD_0
    append_bytes(data, std::vector<float>{0, 1, 0, 0, 1, 0, 0, 1, 0, 0, 1, 0});      // NORMAL
    append_bytes(data, std::vector<uint16_t>{0, 1, 2, 0, 2, 3});
    append_bytes(data, square.colors);
    while (data.size() % 4 != 0) data.push_back(0);
    const std::string colors = square.colors.empty() ? "" : R"(, "COLOR_0": 4)";
    const std::string color_accessor =
        square.colors.empty()
            ? ""
            : R"(, { "bufferView": 2, "componentType": 5121, "normalized": true, "count": 4, "type": "VEC4" })";
    const std::string color_view =
        square.colors.empty() ? "" : R"(, { "buffer": 0, "byteOffset": 140, "byteLength": 16 })";
    return R"({ "asset": { "version": "2.0" }, "scene": 0, "scenes": [{ "nodes": [0] }], "nodes": [{ "mesh": 0 }],
  "meshes": [{ "primitives": [{ "attributes": { "POSITION": 0, "TEXCOORD_0": 1, "NORMAL": 3)" +
           colors + R"( }, "indices": 2, "material": 0 }] }],
  "materials": [{ )" +
           square.material_extra + R"("pbrMetallicRoughness": { "metallicFactor": 0, "baseColorFactor": )" +
           square.base_color_factor + R"(, "baseColorTexture": { )" + square.texture_info_extra + R"("index": 0 } } }],
  "textures": [{ "source": 0)" +
           (square.sampler.empty() ? "" : ", \"sampler\": 0") + R"( }],)" +
           (square.sampler.empty() ? "" : "\n  \"samplers\": [" + square.sampler + "],") + square.top_extra + R"(
  "images": [{ "uri": "data:image/png;base64,)" +
           base64(png_bytes(square.width, square.height, square.rgba)) + R"(" }],
  "accessors": [{ "bufferView": 0, "componentType": 5126, "count": 4, "type": "VEC3", "min": [-1, 0, -1], "max": [1, 0, 1] },
                { "bufferView": 0, "byteOffset": 48, "componentType": 5126, "count": 4, "type": "VEC2" },
                { "bufferView": 1, "componentType": 5123, "count": 6, "type": "SCALAR" },
                { "bufferView": 0, "byteOffset": 80, "componentType": 5126, "count": 4, "type": "VEC3" })" +
           color_accessor + R"(],
  "bufferViews": [{ "buffer": 0, "byteOffset": 0, "byteLength": 128 }, { "buffer": 0, "byteOffset": 128, "byteLength": 12 })" +
           color_view + R"(],
  "buffers": [{ "byteLength": )" +
           std::to_string(data.size()) + R"(, "uri": "data:application/octet-stream;base64,)" + base64(data) +
           R"(" }] })";
}

}  // namespace vkw::test
