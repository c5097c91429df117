// Small glTF 2.0 files that the tests write themselves (one embedded base64 buffer), so that
// the expected vertex counts, indices and bounds are known exactly.
#pragma once

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

namespace vkw::test {

struct GltfSpec {
    std::vector<float> positions;   // xyz per vertex
    std::vector<float> normals;     // empty: no NORMAL attribute
    std::vector<uint16_t> indices;  // empty: not indexed
    int mode = 4;                   // TRIANGLES
    std::string node_extra;         // e.g. R"("translation": [1, 2, 3], )"
    std::string material;           // a materials[0] object; empty: no material
    std::string top_extra;          // more top-level members, each followed by a comma
    int second_mode = -1;           // >= 0: a second primitive of the same vertices in this mode
    std::string primitive_extra;    // more members of the first primitive, each followed by a comma
};

inline std::string base64(const std::vector<unsigned char>& bytes) {
    static constexpr char kDigits[] = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    std::string out;
    for (std::size_t i = 0; i < bytes.size(); i += 3) {
        const uint32_t n = uint32_t(bytes[i]) << 16 | (i + 1 < bytes.size() ? uint32_t(bytes[i + 1]) << 8 : 0) |
                           (i + 2 < bytes.size() ? bytes[i + 2] : 0);
        out += kDigits[n >> 18 & 63];
        out += kDigits[n >> 12 & 63];
        out += i + 1 < bytes.size() ? kDigits[n >> 6 & 63] : '=';
        out += i + 2 < bytes.size() ? kDigits[n & 63] : '=';
    }
    return out;
}

template <class T>
void append_bytes(std::vector<unsigned char>& out, const std::vector<T>& values) {
    const std::size_t at = out.size();
    out.resize(at + values.size() * sizeof(T));
    if (!values.empty()) std::memcpy(out.data() + at, values.data(), values.size() * sizeof(T));
}

// The spec's one buffer: positions, normals, then indices, padded to a multiple of 4 bytes.
inline std::vector<unsigned char> gltf_buffer(const GltfSpec& spec) {
    std::vector<unsigned char> data;
    append_bytes(data, spec.positions);
    append_bytes(data, spec.normals);
    append_bytes(data, spec.indices);
    while (data.size() % 4 != 0) data.push_back(0);
    return data;
}

inline std::string gltf_text(const GltfSpec& spec) {
    std::vector<unsigned char> data;
    append_bytes(data, spec.positions);
    append_bytes(data, spec.normals);
    const std::size_t index_offset = data.size();
    append_bytes(data, spec.indices);
    const std::size_t count = spec.positions.size() / 3;
    float lo[3] = {1e30f, 1e30f, 1e30f}, hi[3] = {-1e30f, -1e30f, -1e30f};
    for (std::size_t i = 0; i < spec.positions.size(); ++i) {
        lo[i % 3] = std::min(lo[i % 3], spec.positions[i]);
        hi[i % 3] = std::max(hi[i % 3], spec.positions[i]);
    }
    const auto vec = [](const float* v) {
        return "[" + std::to_string(v[0]) + ", " + std::to_string(v[1]) + ", " + std::to_string(v[2]) + "]";
    };
    std::string attributes = R"("POSITION": 0)";
    std::string accessors = R"({ "bufferView": 0, "componentType": 5126, "count": )" + std::to_string(count) +
                            R"(, "type": "VEC3", "min": )" + vec(lo) + R"(, "max": )" + vec(hi) + " }";
    int next = 1;
    if (!spec.normals.empty()) {
        attributes += R"(, "NORMAL": 1)";
        accessors += R"(, { "bufferView": 0, "byteOffset": )" + std::to_string(count * 12) +
                     R"(, "componentType": 5126, "count": )" + std::to_string(count) + R"(, "type": "VEC3" })";
        ++next;
    }
    std::string primitive =
        "{ " + spec.primitive_extra + R"("attributes": { )" + attributes + " }, \"mode\": " + std::to_string(spec.mode);
    std::string views = R"({ "buffer": 0, "byteOffset": 0, "byteLength": )" + std::to_string(index_offset) + " }";
    if (!spec.indices.empty()) {
        primitive += ", \"indices\": " + std::to_string(next);
        accessors += R"(, { "bufferView": 1, "componentType": 5123, "count": )" + std::to_string(spec.indices.size()) +
                     R"(, "type": "SCALAR" })";
        views += R"(, { "buffer": 0, "byteOffset": )" + std::to_string(index_offset) + R"(, "byteLength": )" +
                 std::to_string(spec.indices.size() * 2) + " }";
    }
    if (!spec.material.empty()) primitive += R"(, "material": 0)";
    primitive += " }";
    if (spec.second_mode >= 0) {
        primitive +=
            R"(, { "attributes": { )" + attributes + " }, \"mode\": " + std::to_string(spec.second_mode) + " }";
    }
    while (data.size() % 4 != 0) data.push_back(0);
    return R"({ "asset": { "version": "2.0" }, "scene": 0, "scenes": [{ "nodes": [0] }],
  "nodes": [{ )" +
           spec.node_extra + R"("mesh": 0 }],
  "meshes": [{ "name": "Test", "primitives": [)" +
           primitive + R"(] }],)" + (spec.material.empty() ? "" : "\n  \"materials\": [" + spec.material + "],") +
           spec.top_extra + R"(
  "accessors": [)" +
           accessors + R"(],
  "bufferViews": [)" +
           views + R"(],
  "buffers": [{ "byteLength": )" +
           std::to_string(data.size()) + R"(, "uri": "data:application/octet-stream;base64,)" + base64(data) +
           R"(" }] })";
}

// gltf_text with the buffer in a file of its own: `uri` as the glTF names it, `bin_file` where
// the test writes the bytes.
inline std::string gltf_text_with_buffer_file(const GltfSpec& spec, const std::string& uri,
                                              const std::filesystem::path& bin_file) {
    const std::vector<unsigned char> data = gltf_buffer(spec);
    std::ofstream(bin_file, std::ios::binary)
        .write(reinterpret_cast<const char*>(data.data()), std::streamsize(data.size()));
    std::string text = gltf_text(spec);
    const std::size_t begin = text.find("data:application/octet-stream");
    return text.replace(begin, text.find('"', begin) - begin, uri);
}

// Two squares in y = 0 facing +y, side by side: x in [-1, 0] (primitive 0, material 0) and
// x in [0, 1] (primitive 1, material 1), z in [-1, 1]; `materials` is the materials array's
// contents (two objects). Six indices per primitive, in one buffer of positions then indices.
inline std::string two_material_squares(const std::string& materials) {
    std::vector<unsigned char> data;
    append_bytes(data, std::vector<float>{-1, 0, -1, -1, 0, 1, 0, 0, 1, 0, 0, -1,    // left square
                                          0,  0, -1, 0,  0, 1, 1, 0, 1, 1, 0, -1});  // right square
    append_bytes(data, std::vector<uint16_t>{0, 1, 2, 0, 2, 3, 4, 5, 6, 4, 6, 7});
    return R"({ "asset": { "version": "2.0" }, "scene": 0, "scenes": [{ "nodes": [0] }], "nodes": [{ "mesh": 0 }],
  "meshes": [{ "primitives": [{ "attributes": { "POSITION": 0 }, "indices": 1, "material": 0 },
                              { "attributes": { "POSITION": 0 }, "indices": 2, "material": 1 }] }],
  "materials": [)" +
           materials + R"(],
  "accessors": [{ "bufferView": 0, "componentType": 5126, "count": 8, "type": "VEC3",
                  "min": [-1, 0, -1], "max": [1, 0, 1] },
                { "bufferView": 1, "componentType": 5123, "count": 6, "type": "SCALAR" },
                { "bufferView": 1, "byteOffset": 12, "componentType": 5123, "count": 6, "type": "SCALAR" }],
  "bufferViews": [{ "buffer": 0, "byteOffset": 0, "byteLength": 96 }, { "buffer": 0, "byteOffset": 96, "byteLength": 24 }],
  "buffers": [{ "byteLength": 120, "uri": "data:application/octet-stream;base64,)" +
           base64(data) + R"(" }] })";
}

// A fresh folder for one test's files.
inline std::filesystem::path scratch_dir(const std::string& name) {
    const std::filesystem::path dir = std::filesystem::path(::testing::TempDir()) / ("vkwater_scene_" + name);
    std::filesystem::remove_all(dir);
    std::filesystem::create_directories(dir);
    return dir;
}

inline std::filesystem::path write_text(const std::filesystem::path& file, const std::string& text) {
    std::ofstream(file, std::ios::binary) << text;
    return file;
}

// A square pyramid: apex (0, 2, 0) over the base [-1, 1] x [-1, 1] at y = 0; 5 vertices,
// 6 triangles, all counter-clockwise seen from outside.
inline GltfSpec pyramid() {
    GltfSpec spec;
    spec.positions = {0, 2, 0, -1, 0, -1, 1, 0, -1, 1, 0, 1, -1, 0, 1};
    spec.indices = {1, 0, 2, 2, 0, 3, 3, 0, 4, 4, 0, 1, 1, 2, 3, 1, 3, 4};
    return spec;
}

}  // namespace vkw::test
