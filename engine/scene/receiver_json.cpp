// One element of "receivers": a built-in shape (builtin_meshes.hpp) or a glTF mesh
// (gltf_mesh.hpp) with its transform and albedo, turned into a world-space Mesh. The type
// decides the shape's fields: those of another type are unknown fields.
#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

#include "engine/core/errors.hpp"
#include "engine/core/message_text.hpp"
#include "engine/scene/angles.hpp"
#include "engine/scene/builtin_meshes.hpp"
#include "engine/scene/file_scope.hpp"
#include "engine/scene/gltf_mesh.hpp"
#include "engine/scene/scene_json.hpp"

namespace vkw {
namespace {

constexpr std::array<Named<ReceiverType>, 5> kTypes = {{
    {"plane", ReceiverType::Plane},
    {"box", ReceiverType::Box},
    {"sphere", ReceiverType::Sphere},
    {"terrain", ReceiverType::Terrain},
    {"gltf", ReceiverType::Gltf},
}};

// gltf "texture": use the material's baseColorTexture, or ignore it (albedo alone).
constexpr std::array<Named<bool>, 2> kTextureUse = {{{"material", true}, {"none", false}}};

// Every shape field of every type, declared when the type itself is missing.
constexpr std::array<std::string_view, 8> kShapeFields = {"half_size", "radius", "size", "resolution",
                                                          "height",    "seed",   "file", "texture"};

Mesh read_gltf(FieldReader& fields, const FileScope& scope, const std::optional<glm::dvec3>& albedo) {
    const auto file = fields.optional_string("file");
    const bool use_texture = fields.choice("texture", kTextureUse, true);
    fields.finish();
    if (!file) fields.fail("file", "missing required field", "a glTF 2.0 file (.gltf or .glb), relative to the scene");
    Mesh mesh;
    try {
        mesh = load_gltf_mesh(scope.resolve(scope.scene_folder(), *file, "the glTF file"), scope);
    } catch (const UserError& error) {
        fields.fail("file", error.what());
    }
    // Each warning names the receiver's file, as an error would.
    for (std::string& warning : mesh.warnings) {
        warning = fields.path_of("file") + " '" + shortened_input(*file, 60) + "': " + warning;
    }
    if (!use_texture) {
        for (MeshPart& part : mesh.parts) part.texture = -1;
        mesh.textures.clear();
    }
    // A given albedo replaces the file's base colour whole: the materials' factors and textures and
    // the vertex colours (it does not multiply them).
    if (albedo) {
        mesh.parts.clear();
        mesh.textures.clear();
        mesh.colors.clear();
    }
    return mesh;
}

// The receiver's mesh in object space; a terrain's shape in `terrain` too.
Mesh read_shape(FieldReader& fields, ReceiverType type, const FileScope& scope, const std::optional<glm::dvec3>& albedo,
                std::optional<TerrainShape>& terrain) {
    switch (type) {
        case ReceiverType::Plane: return make_plane_mesh(fields.vec2("half_size", Range::positive_length()));
        case ReceiverType::Box: return make_box_mesh(fields.vec3("half_size", Range::positive_length()));
        case ReceiverType::Sphere: return make_sphere_mesh(fields.number("radius", Range::positive_length()));
        case ReceiverType::Terrain: {
            const TerrainShape defaults;
            TerrainShape shape;
            shape.size = fields.number("size", Range::positive_length());
            shape.resolution = static_cast<uint32_t>(
                fields.integer("resolution", Range::closed(2.0, 2048.0, "cells per side"), defaults.resolution));
            shape.height = fields.number("height", Range::nonnegative_length());
            shape.seed = static_cast<uint64_t>(
                fields.integer("seed", Range::closed(0.0, kMaxExactInteger), static_cast<int64_t>(defaults.seed)));
            fields.finish();  // no mesh from placeholders of missing fields
            terrain = shape;
            return make_terrain_mesh(shape);
        }
        case ReceiverType::Gltf: return read_gltf(fields, scope, albedo);
    }
    return {};
}

}  // namespace

Receiver read_receiver(FieldReader& fields, const FileScope& scope) {
    Receiver receiver;
    receiver.name = fields.string("name", fields.path_of(""));
    const auto type = fields.required_choice("type", kTypes);
    const std::optional<glm::dvec3> albedo = fields.optional_vec3("albedo", Range::closed(0.0, 1.0));
    const glm::dvec3 translation = fields.vec3("translation", Range::length(), glm::dvec3(0.0));
    const glm::dvec3 rotation = fields.vec3("rotation_deg", Range::closed(-360.0, 360.0, "degrees"), glm::dvec3(0.0));
    const glm::dvec3 scale =
        fields.vec3("scale", Range{.min = 0.0, .max = kMaxSceneLength, .min_inclusive = false}, glm::dvec3(1.0));
    if (!type) {
        for (const std::string_view key : kShapeFields) fields.declare({key});
        fields.finish();  // reports a misspelt type, or the missing one
    }
    receiver.type = *type;
    receiver.mesh = read_shape(fields, receiver.type, scope, albedo, receiver.terrain);
    fields.finish();
    receiver.albedo = albedo.value_or(receiver.albedo);

    glm::dmat4 object_to_world(euler_xyz_deg(rotation));
    for (int axis = 0; axis < 3; ++axis) object_to_world[axis] *= scale[axis];
    object_to_world[3] = glm::dvec4(translation, 1.0);
    receiver.object_to_world = object_to_world;
    transform_mesh(receiver.mesh, object_to_world);
    // The placed mesh within the scene's lengths (Range::length), however scale and shape combine.
    // A NaN or infinite vertex (a glTF file can hold one) is refused too.
    double reach = 0.0;
    for (const glm::vec3& position : receiver.mesh.positions) {
        for (int axis = 0; axis < 3; ++axis) {
            const double value = std::abs(double(position[axis]));
            reach = std::isfinite(value) ? std::max(reach, value) : std::numeric_limits<double>::infinity();
        }
    }
    if (!std::isfinite(reach)) {
        fields.fail(receiver.type == ReceiverType::Gltf ? "file" : "scale",
                    "the mesh holds a vertex that is not a finite number once placed",
                    "finite vertices within " + format_number(kMaxSceneLength) + " m of the origin");
    }
    if (!(reach <= kMaxSceneLength)) {
        fields.fail("scale", "places the mesh " + format_number(reach) + " m from the origin",
                    "every vertex within " + format_number(kMaxSceneLength) + " m of it");
    }
    return receiver;
}

}  // namespace vkw
