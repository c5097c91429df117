// What a glTF material asks for that the renderers leave out (gltf_material_note.hpp).
#include "engine/scene/gltf_material_note.hpp"

#include <tiny_gltf.h>

#include <vector>

#include "engine/core/message_text.hpp"
#include "engine/scene/range.hpp"

namespace vkw {

std::string gltf_material_note(const tinygltf::Material& material, int index) {
    std::vector<std::string> ignored;
    const tinygltf::PbrMetallicRoughness& pbr = material.pbrMetallicRoughness;
    if (pbr.metallicRoughnessTexture.index >= 0) ignored.push_back("metallicRoughnessTexture");
    if (material.normalTexture.index >= 0) ignored.push_back("normalTexture");
    if (material.occlusionTexture.index >= 0) ignored.push_back("occlusionTexture");
    if (material.emissiveTexture.index >= 0) ignored.push_back("emissiveTexture");
    const std::vector<double>& emissive = material.emissiveFactor;
    if (emissive.size() == 3 && (emissive[0] != 0.0 || emissive[1] != 0.0 || emissive[2] != 0.0)) {
        ignored.push_back("emissiveFactor");
    }
    if (material.alphaMode == "BLEND") ignored.push_back("alphaMode BLEND (drawn opaque)");
    for (const auto& [name, value] : material.extensions) {
        if (name.starts_with("KHR_materials_")) ignored.push_back(name);
    }
    const bool metallic = pbr.metallicFactor >= 0.5;
    if (ignored.empty() && !metallic) return {};
    std::string note = "materials[" + std::to_string(index) + "]";
    if (!material.name.empty()) note += " '" + shortened_input(material.name, 40) + "'";
    note += ":";
    if (metallic) note += " drawn as Lambertian (metallicFactor " + format_number(pbr.metallicFactor) + ")";
    if (!ignored.empty()) {
        note += std::string(metallic ? ";" : "") + " ignored:";
        for (std::size_t i = 0; i < ignored.size(); ++i) note += (i ? ", " : " ") + ignored[i];
    }
    return note;
}

}  // namespace vkw
