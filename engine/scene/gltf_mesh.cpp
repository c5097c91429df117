// glTF 2.0 to Mesh through tinygltf (see gltf_mesh.hpp). Debian's tinygltf is a compiled shared
// library: no TINYGLTF_IMPLEMENTATION or STB_IMAGE_IMPLEMENTATION here.
#include "engine/scene/gltf_mesh.hpp"

#include <tiny_gltf.h>

#include <algorithm>
#include <array>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <initializer_list>
#include <map>
#include <memory>
#include <set>
#include <string>
#include <vector>

#include <glm/gtc/quaternion.hpp>

#include "engine/core/errors.hpp"
#include "engine/core/message_text.hpp"
#include "engine/scene/file_scope.hpp"
#include "engine/scene/gltf_material_note.hpp"
#include "engine/scene/gltf_texture.hpp"
#include "engine/scene/json_text.hpp"
#include "engine/scene/range.hpp"

namespace vkw {
namespace {

// Deeper node hierarchies than this are taken for a cycle (malformed) rather than recursed into.
constexpr int kMaxNodeDepth = 64;

const char* mode_name(int mode) {
    switch (mode) {
        case TINYGLTF_MODE_POINTS: return "POINTS";
        case TINYGLTF_MODE_LINE: return "LINES";
        case TINYGLTF_MODE_LINE_LOOP: return "LINE_LOOP";
        case TINYGLTF_MODE_LINE_STRIP: return "LINE_STRIP";
        case TINYGLTF_MODE_TRIANGLES: return "TRIANGLES";
        case TINYGLTF_MODE_TRIANGLE_STRIP: return "TRIANGLE_STRIP";
        case TINYGLTF_MODE_TRIANGLE_FAN: return "TRIANGLE_FAN";
        default: return "unknown";
    }
}

template <class T>
T load(const unsigned char* at) {
    T value;
    std::memcpy(&value, at, sizeof value);
    return value;
}

// One component at `at`: normalised integers mapped to [0, 1] or [-1, 1] as the glTF
// specification states; plain integers (indices) converted exactly.
double component(const unsigned char* at, int type, bool normalized) {
    switch (type) {
        case TINYGLTF_COMPONENT_TYPE_FLOAT: return load<float>(at);
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT: return load<uint32_t>(at);
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: {
            const double v = load<uint16_t>(at);
            return normalized ? v / 65535.0 : v;
        }
        case TINYGLTF_COMPONENT_TYPE_SHORT: {
            const double v = load<int16_t>(at);
            return normalized ? std::max(v / 32767.0, -1.0) : v;
        }
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: return normalized ? *at / 255.0 : *at;
        case TINYGLTF_COMPONENT_TYPE_BYTE: {
            const double v = load<int8_t>(at);
            return normalized ? std::max(v / 127.0, -1.0) : v;
        }
        default: return 0.0;
    }
}

// A primitive's vertex sequence as a triangle list. Strips alternate their winding; the
// odd triangles are reordered so that every triangle keeps the first one's orientation.
std::vector<uint32_t> triangle_list(int mode, const std::vector<uint32_t>& order) {
    if (mode == TINYGLTF_MODE_TRIANGLES) return {order.begin(), order.end() - std::ptrdiff_t(order.size() % 3)};
    std::vector<uint32_t> triangles;
    for (std::size_t i = 2; i < order.size(); ++i) {
        if (mode == TINYGLTF_MODE_TRIANGLE_FAN) {
            triangles.insert(triangles.end(), {order[0], order[i - 1], order[i]});
        } else if (i % 2 == 0) {
            triangles.insert(triangles.end(), {order[i - 2], order[i - 1], order[i]});
        } else {
            triangles.insert(triangles.end(), {order[i - 1], order[i - 2], order[i]});
        }
    }
    return triangles;
}

glm::dmat4 local_transform(const tinygltf::Node& node) {
    glm::dmat4 local(1.0);
    if (node.matrix.size() == 16) {
        for (int i = 0; i < 16; ++i) local[i / 4][i % 4] = node.matrix[std::size_t(i)];  // column-major, as glm
        return local;
    }
    glm::dmat4 rotation(1.0), scale(1.0);
    const std::vector<double>& t = node.translation;
    if (t.size() == 3) local[3] = glm::dvec4(t[0], t[1], t[2], 1.0);
    if (node.rotation.size() == 4) {
        rotation = glm::mat4_cast(glm::dquat(node.rotation[3], node.rotation[0], node.rotation[1], node.rotation[2]));
    }
    for (std::size_t i = 0; i < node.scale.size() && i < 3; ++i) scale[int(i)][int(i)] = node.scale[i];
    return local * rotation * scale;  // T R S
}

class GltfReader {
public:
    GltfReader(const std::filesystem::path& file, const tinygltf::Model& model) : file_(file), model_(model) {}

    [[noreturn]] void fail(const std::string& what) const {
        throw UserError("glTF file '" + file_.string() + "': " + what);
    }

    void add_node(Mesh& mesh, int index, const glm::dmat4& parent, int depth) {
        if (index < 0 || std::size_t(index) >= model_.nodes.size()) fail("no node " + std::to_string(index));
        if (depth > kMaxNodeDepth) fail("nodes nested more than " + std::to_string(kMaxNodeDepth) + " deep (a cycle?)");
        const tinygltf::Node& node = model_.nodes[std::size_t(index)];
        const glm::dmat4 transform = parent * local_transform(node);
        if (node.skin >= 0 && node.mesh >= 0) skinned_.push_back("nodes[" + std::to_string(index) + "]");
        if (node.mesh >= 0) add_mesh(mesh, node.mesh, transform);
        for (const int child : node.children) add_node(mesh, child, transform, depth + 1);
    }

    void add_mesh(Mesh& mesh, int index, const glm::dmat4& transform) {
        if (index < 0 || std::size_t(index) >= model_.meshes.size()) fail("no mesh " + std::to_string(index));
        const tinygltf::Mesh& source = model_.meshes[std::size_t(index)];
        const std::string name = "meshes[" + std::to_string(index) + "]";
        for (std::size_t p = 0; p < source.primitives.size(); ++p) {
            const std::string mesh_name = source.name.empty() ? name : "mesh '" + source.name + "' (" + name + ")";
            add_primitive(mesh, source.primitives[p], mesh_name + ", primitive " + std::to_string(p), transform);
        }
    }

    // After the last primitive: one line for each kind of content left out, naming the first few.
    void add_content_warnings(Mesh& mesh) const {
        const auto listed = [](const std::vector<std::string>& names) {
            std::string text;
            for (std::size_t i = 0; i < names.size() && i < 3; ++i) text += (i ? "; " : "") + names[i];
            if (names.size() > 3) text += "; and " + std::to_string(names.size() - 3) + " more";
            return text;
        };
        if (!skipped_.empty()) mesh.warnings.push_back("skipped, not triangles: " + listed(skipped_));
        if (!skinned_.empty()) mesh.warnings.push_back("skins ignored, drawn in the bind pose: " + listed(skinned_));
        if (!morphed_.empty()) {
            mesh.warnings.push_back("morph targets ignored, drawn in the base shape: " + listed(morphed_));
        }
        if (!untextured_.empty()) {
            mesh.warnings.push_back("base colour texture without its coordinates, drawn untextured: " +
                                    listed(untextured_));
        }
    }

private:
    // Elements of accessor `index` as doubles, `width` components each; `kinds` lists the
    // accepted component types. Bounds are checked so that malformed files cannot read past
    // their buffers.
    std::vector<double> read(int index, int width, std::initializer_list<int> kinds, const std::string& what) const {
        const std::string name = "accessors[" + std::to_string(index) + "]";
        if (index < 0 || std::size_t(index) >= model_.accessors.size()) fail(what + ": no " + name);
        const tinygltf::Accessor& accessor = model_.accessors[std::size_t(index)];
        if (accessor.sparse.isSparse) fail(what + ": sparse accessors are not supported");
        if (tinygltf::GetNumComponentsInType(uint32_t(accessor.type)) != width ||
            std::find(kinds.begin(), kinds.end(), accessor.componentType) == kinds.end()) {
            fail(what + ": unsupported type or component type in " + name);
        }
        if (accessor.bufferView < 0 || std::size_t(accessor.bufferView) >= model_.bufferViews.size()) {
            fail(what + ": " + name + " has no bufferView");
        }
        const tinygltf::BufferView& view = model_.bufferViews[std::size_t(accessor.bufferView)];
        if (view.buffer < 0 || std::size_t(view.buffer) >= model_.buffers.size()) {
            fail(what + ": bufferView has no buffer");
        }
        const std::vector<unsigned char>& data = model_.buffers[std::size_t(view.buffer)].data;
        const auto size = std::size_t(tinygltf::GetComponentSizeInBytes(uint32_t(accessor.componentType)));
        const std::size_t element = size * std::size_t(width);
        const std::size_t stride = view.byteStride != 0 ? view.byteStride : element;
        // The view within its buffer and the accessor's last element within the view, in
        // arithmetic that cannot wrap (a count or an offset near 2^64 once read outside the buffer).
        const auto fits = [](uint64_t offset, uint64_t length, uint64_t limit) {
            return offset <= limit && length <= limit - offset;
        };
        uint64_t span = 0;
        const bool inside =
            fits(view.byteOffset, view.byteLength, data.size()) &&
            (accessor.count == 0 || (!__builtin_mul_overflow(uint64_t(stride), uint64_t(accessor.count - 1), &span) &&
                                     !__builtin_add_overflow(span, uint64_t(element), &span) &&
                                     fits(accessor.byteOffset, span, view.byteLength)));
        if (!inside) fail(what + ": " + name + " reaches past the end of its buffer");
        std::vector<double> values;
        values.reserve(accessor.count * std::size_t(width));
        const unsigned char* base = data.data() + view.byteOffset + accessor.byteOffset;
        for (std::size_t i = 0; i < accessor.count; ++i) {
            for (std::size_t c = 0; c < std::size_t(width); ++c) {
                values.push_back(component(base + i * stride + c * size, accessor.componentType, accessor.normalized));
            }
        }
        return values;
    }

    // The primitive's vertices in drawing order: its indices, or 0, 1, 2, ... without them.
    std::vector<uint32_t> vertex_order(const tinygltf::Primitive& primitive, std::size_t count,
                                       const std::string& where) const {
        std::vector<uint32_t> order;
        if (primitive.indices < 0) {
            for (std::size_t i = 0; i < count; ++i) order.push_back(uint32_t(i));
            return order;
        }
        const auto kinds = {TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE, TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT,
                            TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT};
        for (const double i : read(primitive.indices, 1, kinds, where + " indices")) {
            if (i >= double(count)) {
                fail(where + ": index " + std::to_string(uint64_t(i)) + " >= vertex count " + std::to_string(count));
            }
            order.push_back(uint32_t(i));
        }
        return order;
    }

    void add_primitive(Mesh& mesh, const tinygltf::Primitive& primitive, const std::string& where,
                       const glm::dmat4& transform) {
        const int mode = primitive.mode;
        if (mode < TINYGLTF_MODE_TRIANGLES || mode > TINYGLTF_MODE_TRIANGLE_FAN) {  // lists, strips and fans
            if (mode < TINYGLTF_MODE_POINTS || mode > TINYGLTF_MODE_TRIANGLE_FAN) {
                fail(
                    where + ": mode " + std::to_string(mode) +
                    " is not a glTF primitive mode (accepted: 0 to 6; drawn: TRIANGLES, TRIANGLE_STRIP, TRIANGLE_FAN)");
            }
            skipped_.push_back(where + " (" + mode_name(mode) + ")");  // points and lines: nothing to light
            return;
        }
        if (!primitive.targets.empty()) morphed_.push_back(where);
        const auto attribute = [&](const char* name) {
            const auto it = primitive.attributes.find(name);
            return it == primitive.attributes.end() ? -1 : it->second;
        };
        if (attribute("POSITION") < 0) fail(where + ": no POSITION attribute");
        const auto floats = {TINYGLTF_COMPONENT_TYPE_FLOAT};
        const std::vector<double> positions = read(attribute("POSITION"), 3, floats, where + " POSITION");
        const std::size_t count = positions.size() / 3;
        std::vector<double> normals;
        if (attribute("NORMAL") >= 0) normals = read(attribute("NORMAL"), 3, floats, where + " NORMAL");
        if (!normals.empty() && normals.size() != positions.size()) fail(where + ": NORMAL and POSITION counts differ");
        // The base colour texture and the coordinates it reads (TEXCOORD_0 for an untextured part).
        int texture = -1;
        UvMapping mapping;
        if (primitive.material >= 0) {
            const tinygltf::TextureInfo& info =
                material(primitive.material, where).pbrMetallicRoughness.baseColorTexture;
            if (info.index >= 0) {
                mapping = uv_mapping(info);
                texture = texture_index(mesh, info.index, where);
            }
        }
        const std::string uv_name = "TEXCOORD_" + std::to_string(mapping.set);
        if (texture >= 0 && attribute(uv_name.c_str()) < 0) {
            untextured_.push_back(where + " (no " + uv_name + ")");
            texture = -1;
        }
        std::vector<double> uvs;
        if (attribute(uv_name.c_str()) >= 0) {
            const auto kinds = {TINYGLTF_COMPONENT_TYPE_FLOAT, TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE,
                                TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT};
            uvs = read(attribute(uv_name.c_str()), 2, kinds, where + " " + uv_name);
            if (uvs.size() / 2 != count) fail(where + ": " + uv_name + " and POSITION counts differ");
        }
        const std::vector<double> colors = vertex_colors(attribute("COLOR_0"), count, where);
        const std::vector<uint32_t> triangles = triangle_list(mode, vertex_order(primitive, count, where));
        const auto first_index = uint32_t(mesh.indices.size());

        const glm::dmat3 normal_matrix = glm::transpose(glm::inverse(glm::dmat3(transform)));
        const bool mirrored = glm::determinant(glm::dmat3(transform)) < 0.0;  // flips the winding
        const auto position = [&](uint32_t i) {
            const glm::dvec3 p(positions[3 * i], positions[3 * i + 1], positions[3 * i + 2]);
            return glm::dvec3(transform * glm::dvec4(p, 1.0));
        };
        // uvs and colors stay one per position: once any primitive has them, the others get (0, 0)
        // and white.
        if (!uvs.empty() && !has_uvs_) mesh.uvs.resize(mesh.positions.size(), glm::vec2(0.0f));
        if (!colors.empty() && !has_colors_) mesh.colors.resize(mesh.positions.size(), glm::vec4(1.0f));
        has_uvs_ = has_uvs_ || !uvs.empty();
        has_colors_ = has_colors_ || !colors.empty();
        const auto push_vertex = [&](uint32_t i, const glm::dvec3& normal) {
            mesh.positions.emplace_back(position(i));
            mesh.normals.emplace_back(normal);
            if (has_uvs_) {
                const glm::dvec3 uv = uvs.empty() ? glm::dvec3(0.0, 0.0, 1.0)
                                                  : mapping.transform * glm::dvec3(uvs[2 * i], uvs[2 * i + 1], 1.0);
                const glm::vec2 stored(uv.x, uv.y);
                if (!std::isfinite(stored.x) || !std::isfinite(stored.y)) {
                    fail(where + ": " + uv_name + " of vertex " + std::to_string(i) +
                         " is not finite (after KHR_texture_transform, if any; accepted: finite in single precision)");
                }
                mesh.uvs.push_back(stored);
            }
            if (has_colors_) {
                mesh.colors.push_back(
                    colors.empty() ? glm::vec4(1.0f)
                                   : glm::vec4(colors[4 * i], colors[4 * i + 1], colors[4 * i + 2], colors[4 * i + 3]));
            }
        };
        const bool flat = normals.empty();  // the specification asks for flat normals then
        const auto base = uint32_t(mesh.positions.size());
        for (uint32_t i = 0; !flat && i < count; ++i) {
            const glm::dvec3 n(normals[3 * i], normals[3 * i + 1], normals[3 * i + 2]);
            push_vertex(i, glm::normalize(normal_matrix * n));
        }
        for (std::size_t t = 0; t + 2 < triangles.size(); t += 3) {
            std::array<uint32_t, 3> tri = {triangles[t], triangles[t + 1], triangles[t + 2]};
            if (mirrored) std::swap(tri[1], tri[2]);
            if (!flat) {
                for (const uint32_t i : tri) mesh.indices.push_back(base + i);
                continue;
            }
            const glm::dvec3 a = position(tri[0]);
            const glm::dvec3 cross = glm::cross(position(tri[1]) - a, position(tri[2]) - a);
            const glm::dvec3 n = glm::length(cross) > 0.0 ? glm::normalize(cross) : glm::dvec3(0.0, 1.0, 0.0);
            for (const uint32_t i : tri) {
                mesh.indices.push_back(uint32_t(mesh.positions.size()));
                push_vertex(i, n);
            }
        }
        MeshPart part{first_index, 0, base_color(primitive.material, where), texture};
        if (primitive.material >= 0) {
            const tinygltf::Material& source = material(primitive.material, where);
            const std::vector<double>& factor = source.pbrMetallicRoughness.baseColorFactor;
            if (factor.size() == 4) part.alpha = std::clamp(factor[3], 0.0, 1.0);
            if (source.alphaMode == "MASK") part.alpha_cutoff = alpha_cutoff(source, primitive.material);
        }
        add_part(mesh, part);
        if (primitive.material >= 0 && noted_materials_.insert(primitive.material).second) {
            const std::string note =
                gltf_material_note(model_.materials[std::size_t(primitive.material)], primitive.material);
            if (!note.empty()) mesh.warnings.push_back(note);
        }
    }

    // The primitive's indices as a part of its material's base colour, joined to the previous part
    // when that has the same colour and texture (a file of many primitives but few materials draws
    // few parts).
    static void add_part(Mesh& mesh, MeshPart part) {
        part.index_count = uint32_t(mesh.indices.size()) - part.first_index;
        if (part.index_count == 0) return;
        const MeshPart& last = mesh.parts.empty() ? part : mesh.parts.back();
        if (!mesh.parts.empty() && last.base_color == part.base_color && last.texture == part.texture &&
            last.alpha == part.alpha && last.alpha_cutoff == part.alpha_cutoff) {
            mesh.parts.back().index_count += part.index_count;
            return;
        }
        mesh.parts.push_back(part);
    }

    const tinygltf::Material& material(int index, const std::string& where) const {
        if (std::size_t(index) >= model_.materials.size()) fail(where + ": no material " + std::to_string(index));
        return model_.materials[std::size_t(index)];
    }

    // The metallic-roughness base colour factor of material `index` (glTF's default material,
    // white, for a primitive without one): the Lambertian albedo the renderers apply once.
    glm::dvec3 base_color(int index, const std::string& where) const {
        if (index < 0) return glm::dvec3(1.0);
        const std::vector<double>& factor = material(index, where).pbrMetallicRoughness.baseColorFactor;
        if (factor.size() != 4) return glm::dvec3(1.0);
        const glm::dvec3 color(factor[0], factor[1], factor[2]);
        if (!(glm::all(glm::greaterThanEqual(color, glm::dvec3(0.0))) &&
              glm::all(glm::lessThanEqual(color, glm::dvec3(1.0))))) {
            fail("materials[" + std::to_string(index) + "].pbrMetallicRoughness.baseColorFactor " + format_vec3(color) +
                 " is not a valid albedo (accepted: each of r, g, b in [0, 1])");
        }
        return color;
    }

    // The mesh's index of the file's textures[index], added on first use.
    int texture_index(Mesh& mesh, int index, const std::string& where) {
        const auto [at, added] = textures_.try_emplace(index, int(mesh.textures.size()));
        if (!added) return at->second;
        try {
            mesh.textures.push_back(mesh_texture(model_, index, images_));
        } catch (const UserError& error) {
            fail(where + ": " + error.what());
        }
        return at->second;
    }

    // A MASK material's alphaCutoff (glTF's default 0.5), refused outside [0, 1].
    double alpha_cutoff(const tinygltf::Material& source, int index) const {
        const double cutoff = source.alphaCutoff;
        if (!(cutoff >= 0.0 && cutoff <= 1.0)) {
            fail("materials[" + std::to_string(index) + "].alphaCutoff " + format_number(cutoff) +
                 " (accepted: 0 to 1)");
        }
        return cutoff;
    }

    // COLOR_0 as linear RGBA, four per vertex (alpha 1 for an RGB one); empty without it.
    std::vector<double> vertex_colors(int accessor, std::size_t count, const std::string& where) const {
        if (accessor < 0) return {};
        const bool rgba = std::size_t(accessor) < model_.accessors.size() &&
                          model_.accessors[std::size_t(accessor)].type == TINYGLTF_TYPE_VEC4;
        const auto kinds = {TINYGLTF_COMPONENT_TYPE_FLOAT, TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE,
                            TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT};
        const std::vector<double> values = read(accessor, rgba ? 4 : 3, kinds, where + " COLOR_0");
        if (values.size() / (rgba ? 4 : 3) != count) fail(where + ": COLOR_0 and POSITION counts differ");
        std::vector<double> colors;
        colors.reserve(4 * count);
        for (std::size_t i = 0; i < values.size(); ++i) {
            if (!(values[i] >= 0.0 && values[i] <= 1.0)) {
                fail(where + ": COLOR_0 value " + format_number(values[i]) + " (accepted: each component in [0, 1])");
            }
            colors.push_back(values[i]);
            if (!rgba && i % 3 == 2) colors.push_back(1.0);
        }
        return colors;
    }

    const std::filesystem::path& file_;
    const tinygltf::Model& model_;
    bool has_uvs_ = false, has_colors_ = false;                          // some primitive so far had them
    std::map<int, int> textures_;                                        // the file's texture index -> the mesh's
    std::map<int, std::shared_ptr<const TextureImage>> images_;          // decoded images, shared by textures
    std::set<int> noted_materials_;                                      // each material's note once
    std::vector<std::string> skipped_, skinned_, morphed_, untextured_;  // for add_content_warnings
};

// Whole file as bytes, with errno's reason when it cannot be read (as the scene loader does).
std::string read_bytes(const std::filesystem::path& file) {
    errno = 0;
    const std::unique_ptr<std::FILE, int (*)(std::FILE*)> stream(std::fopen(file.c_str(), "rb"), &std::fclose);
    const auto fail_open = [&] {
        throw UserError("cannot open glTF file '" + file.string() + "': " + std::strerror(errno));
    };
    if (!stream) fail_open();
    std::string bytes;
    char buffer[1 << 16];
    std::size_t count = 0;
    while ((count = std::fread(buffer, 1, sizeof buffer, stream.get())) > 0) bytes.append(buffer, count);
    if (std::ferror(stream.get())) fail_open();
    return bytes;
}

// The JSON of a .glb: its 12-byte header (magic "glTF", version 2, total length) and its first
// chunk, which must be the JSON one; lengths are checked in 64 bits against the file's size, so
// that no header can make a reader look outside the bytes.
std::string_view glb_json(const std::string& bytes, const GltfReader& reader) {
    const auto word = [&](std::size_t at) {
        uint32_t value = 0;
        std::memcpy(&value, bytes.data() + at, sizeof value);  // little-endian, as glTF and x86/ARM are
        return value;
    };
    if (bytes.size() < 20) reader.fail("a .glb shorter than its 12-byte header and first chunk header");
    if (word(4) != 2) reader.fail(".glb version " + std::to_string(word(4)) + " (accepted: 2)");
    const uint64_t length = word(8), json_length = word(12);
    if (length > bytes.size()) {
        reader.fail(".glb header says " + std::to_string(length) + " bytes, the file has " +
                    std::to_string(bytes.size()));
    }
    if (word(16) != 0x4E4F534Au) reader.fail(".glb's first chunk is not JSON");
    if (20 + json_length > length) reader.fail(".glb's JSON chunk reaches past the file's length");
    return std::string_view(bytes).substr(20, json_length);
}

// Buffers embedded as data URIs: the two MIME types glTF names for them and whole base64
// (tinygltf took a wrong type and a payload without its padding).
void check_data_uris(const nlohmann::json& document, const GltfReader& reader) {
    const auto buffers = document.find("buffers");
    if (buffers == document.end() || !buffers->is_array()) return;
    for (std::size_t i = 0; i < buffers->size(); ++i) {
        const nlohmann::json& buffer = (*buffers)[i];
        if (!buffer.is_object() || !buffer.contains("uri") || !buffer["uri"].is_string()) continue;
        const std::string& uri = buffer["uri"].get_ref<const std::string&>();
        if (!uri.starts_with("data:")) continue;
        const std::string name = "buffers[" + std::to_string(i) + "].uri";
        const std::size_t comma = uri.find(',');
        const std::string header = uri.substr(0, std::min(comma, std::size_t(64)));
        if (comma == std::string::npos ||
            (header != "data:application/octet-stream;base64" && header != "data:application/gltf-buffer;base64")) {
            reader.fail(name + ": a data URI starting '" + header +
                        "' (accepted: data:application/octet-stream;base64, or data:application/gltf-buffer;base64,)");
        }
        const std::string_view payload = std::string_view(uri).substr(comma + 1);
        const std::size_t text = payload.find_last_not_of('=') + 1;
        const bool digits = std::all_of(payload.begin(), payload.begin() + std::ptrdiff_t(text), [](char c) {
            return std::isalnum(static_cast<unsigned char>(c)) || c == '+' || c == '/';
        });
        if (payload.size() % 4 != 0 || payload.size() - text > 2 || !digits) {
            reader.fail(name + ": the data URI's base64 is malformed (" + std::to_string(payload.size()) +
                        " characters; accepted: A-Z a-z 0-9 + /, padded with = to a multiple of 4)");
        }
    }
}

// Every buffer and image URI that names a file must stay inside the scene's folder tree (tinygltf
// would open "../../etc/passwd" as readily as "rock.bin"). Checked as written and decoded, since
// tinygltf decodes %XX escapes before it opens the file.
void check_file_uris(const nlohmann::json& document, const std::filesystem::path& file, const FileScope& scope,
                     const GltfReader& reader) {
    for (const char* array : {"buffers", "images"}) {
        const auto entries = document.find(array);
        if (entries == document.end() || !entries->is_array()) continue;
        for (std::size_t i = 0; i < entries->size(); ++i) {
            const nlohmann::json& entry = (*entries)[i];
            if (!entry.is_object() || !entry.contains("uri") || !entry["uri"].is_string()) continue;
            const std::string& uri = entry["uri"].get_ref<const std::string&>();
            if (uri.starts_with("data:")) continue;
            const std::string name = std::string(array) + "[" + std::to_string(i) + "].uri";
            // tinygltf gives up decoding at a '%' that does not start a %XX escape and then reads the
            // glTF's own folder as the file (exit 2 on a std::bad_alloc, found by fuzzing): refused here.
            for (std::size_t at = uri.find('%'); at != std::string::npos; at = uri.find('%', at + 1)) {
                const auto hex = [&](std::size_t k) {
                    return k < uri.size() && std::isxdigit(static_cast<unsigned char>(uri[k]));
                };
                if (!hex(at + 1) || !hex(at + 2)) {
                    reader.fail(name + ": the '%' at character " + std::to_string(at + 1) +
                                " does not start a %XX escape (accepted: '%' followed by two hex digits)");
                }
                at += 2;
            }
            std::filesystem::path resolved;
            try {
                scope.resolve(file.parent_path(), uri, name);
                resolved = scope.resolve(file.parent_path(), decode_uri_escapes(uri), name, uri);
            } catch (const UserError& error) {
                reader.fail(error.what());
            }
            // tinygltf would read a folder as a file of 2^64 - 1 bytes (a std::bad_alloc, exit 2).
            std::error_code ignored;
            if (std::filesystem::is_directory(resolved, ignored)) {
                reader.fail(name + " '" + shortened_input(uri, 60) + "' names a folder (accepted: a file)");
            }
        }
    }
}

// Checks the file's JSON before tinygltf parses it: tinygltf's parser recurses (deep nesting in
// `extras` overflowed the stack), and it answers a required extension it lacks with a misleading
// error about the data that extension would have decoded. Returns the images that base colour
// textures sample (the ones to decode).
std::set<int> prescan_json(std::string_view json, const std::filesystem::path& file, const FileScope& scope,
                           const GltfReader& reader) {
    const std::size_t depth = json_nesting_depth(json);
    if (depth > kMaxJsonNesting) {
        reader.fail("JSON nested " + std::to_string(depth) + " levels deep (accepted: at most " +
                    std::to_string(kMaxJsonNesting) + ")");
    }
    const std::size_t nul = json.find('\0');
    if (nul != std::string_view::npos) {
        reader.fail("a NUL byte at byte " + std::to_string(nul) + " of the JSON (glTF JSON is UTF-8 text)");
    }
    const nlohmann::json document = nlohmann::json::parse(json, nullptr, false);
    if (document.is_discarded() || !document.is_object()) return {};  // tinygltf names the syntax error
    check_data_uris(document, reader);
    check_file_uris(document, file, scope, reader);
    const auto required = document.find("extensionsRequired");
    for (const nlohmann::json& name :
         required != document.end() && required->is_array() ? *required : nlohmann::json::array()) {
        // A required extension changes how data is read (Draco and meshopt compress it), and the
        // specification asks a loader to refuse what it lacks; the one implemented maps texture
        // coordinates (gltf_texture.hpp).
        const std::string text = name.is_string() ? name.get<std::string>() : std::string("?");
        if (text == "KHR_texture_transform") continue;
        reader.fail("needs the glTF extension '" + text.substr(0, 64) +
                    "' (extensionsRequired), which vkwater does not support (accepted: KHR_texture_transform)");
    }
    return base_color_images(document);
}

}  // namespace

Mesh load_gltf_mesh(const std::filesystem::path& file) { return load_gltf_mesh(file, FileScope(file, false)); }

Mesh load_gltf_mesh(const std::filesystem::path& file, const FileScope& scope) {
    const std::string bytes = read_bytes(file);
    tinygltf::TinyGLTF loader;
    tinygltf::Model model;
    std::string error, warning;
    const std::string base_dir = file.parent_path().string();
    GltfReader reader(file, model);
    const bool binary = bytes.starts_with("glTF");  // the .glb magic
    GltfImageDecoder decoder(
        prescan_json(binary ? glb_json(bytes, reader) : std::string_view(bytes), file, scope, reader));
    loader.SetImageLoader(&GltfImageDecoder::decode, &decoder);
    const auto length = static_cast<unsigned int>(bytes.size());
    const auto* data = reinterpret_cast<const unsigned char*>(bytes.data());
    const bool loaded = binary ? loader.LoadBinaryFromMemory(&model, &error, &warning, data, length, base_dir)
                               : loader.LoadASCIIFromString(&model, &error, &warning, bytes.data(), length, base_dir);
    if (!decoder.failure().empty()) reader.fail(decoder.failure());  // tinygltf's message would bury it
    if (!loaded) {
        // tinygltf's messages may span lines; a UserError is one line.
        // tinygltf passes nlohmann's syntax errors on, with the whole token last read (a data URI).
        std::string reason =
            error.empty() ? "tinygltf refused it" : without_last_read(error.substr(0, error.find('\n')));
        const std::string nlohmann_prefix = "parse error at ";  // after "[json.exception.parse_error.101] "
        if (const std::size_t at = reason.find(nlohmann_prefix); at != std::string::npos) {
            reason = reason.substr(at + nlohmann_prefix.size());
        }
        reader.fail("malformed glTF: " + shortened_input(reason, 160));
    }
    Mesh mesh;
    if (model.scenes.empty()) {
        for (std::size_t m = 0; m < model.meshes.size(); ++m) reader.add_mesh(mesh, int(m), glm::dmat4(1.0));
    } else {
        const std::size_t scene = model.defaultScene >= 0 ? std::size_t(model.defaultScene) : 0;
        if (scene >= model.scenes.size()) reader.fail("no scene " + std::to_string(scene));
        for (const int node : model.scenes[scene].nodes) reader.add_node(mesh, node, glm::dmat4(1.0), 0);
    }
    reader.add_content_warnings(mesh);
    if (mesh.indices.empty()) {
        // Say why when its primitives were all points or lines.
        const auto skipped = std::find_if(mesh.warnings.begin(), mesh.warnings.end(),
                                          [](const std::string& line) { return line.starts_with("skipped"); });
        reader.fail("contains no triangles" + (skipped == mesh.warnings.end() ? "" : " (" + *skipped + ")"));
    }
    update_bounds(mesh);
    return mesh;
}

}  // namespace vkw
