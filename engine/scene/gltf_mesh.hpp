// Loading a glTF 2.0 file (.gltf with embedded or external buffers, or .glb) into one Mesh.
// The only place tinygltf is included (it is a heavy header): the scene loader and everything
// else see a plain Mesh.
#pragma once

#include <filesystem>

#include "engine/scene/mesh.hpp"

namespace vkw {

class FileScope;

// Every mesh instanced by the nodes of the default scene (the first scene when none is named,
// every mesh when the file has no scenes), with node transforms applied, merged into one Mesh
// in the file's coordinates. Triangle lists, strips and fans are accepted (strips and fans become
// lists); POINTS and LINES modes are refused. Missing normals are computed flat, as the glTF
// specification asks. Each primitive keeps its material's base colour (Mesh::parts; glTF's default
// white without a material): the factor, and the baseColorTexture's image decoded with its sampler
// and its texture coordinates (KHR_texture_transform applied; gltf_texture.hpp). COLOR_0 becomes
// Mesh::colors. Images that no base colour samples are not decoded.
//
// Throws vkw::UserError naming the file for a file that cannot be read, malformed glTF,
// unsupported content and out-of-bounds data: "glTF file '<path>': <what>". The buffers and
// images the file names must resolve inside `scope` (the scene's folder tree, file_scope.hpp);
// without a scope, inside the glTF file's own folder tree.
Mesh load_gltf_mesh(const std::filesystem::path& file, const FileScope& scope);
Mesh load_gltf_mesh(const std::filesystem::path& file);

}  // namespace vkw
