// What a glTF material asks for that the renderers leave out: both shade a receiver as
// Lambertian with the base colour (factor, texture and vertex colour) alone (docs/model.md section 1).
#pragma once

#include <string>

namespace tinygltf {
struct Material;
}

namespace vkw {

// One sentence naming material `index` and each feature of it that is not drawn: a metallic
// factor of 0.5 or more ("drawn as Lambertian"), normal, occlusion, emissive and
// metallic-roughness maps, an emissive colour, alphaMode BLEND (drawn opaque; MASK is drawn as a cutout),
// double-sidedness and KHR_materials_* extensions; empty when the material is drawn as written.
std::string gltf_material_note(const tinygltf::Material& material, int index);

}  // namespace vkw
