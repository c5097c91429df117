// The medium presets, exactly the table of docs/model.md section 1.
#include "engine/scene/medium.hpp"

#include <array>

namespace vkw {
namespace {

// Sources, as cited next to the table in docs/model.md section 1:
// - de la Fuente 2011, table 5.1 and section 5.1: every preset uses pure-water absorption (sigma_a);
//   pure-water scattering from b_w = 0.00288 (lambda / 500 nm)^-4.32 (the "pure" sigma_s);
//   the particle scattering of the clear-ocean, coastal and turbid-harbour waters.
// - Petzold's measured mean cosine of ocean-particle scattering, about 0.92, hence g = 0.9
//   for the three particle-laden presets (pure water's molecular scattering is near
//   isotropic: g = 0).
const std::array<Medium, 4> kPresets = {{
    {"pure", {1.169, 0.0638, 0.0150}, {0.0006, 0.0019, 0.0045}, 0.0},
    {"clear-ocean", {1.169, 0.0638, 0.0150}, {0.028, 0.035, 0.039}, 0.9},
    {"coastal", {1.169, 0.0638, 0.0150}, {0.17, 0.20, 0.234}, 0.9},
    {"turbid-harbour", {1.169, 0.0638, 0.0150}, {0.71, 0.82, 0.96}, 0.9},
}};

}  // namespace

const Medium* find_medium_preset(std::string_view name) {
    for (const Medium& preset : kPresets) {
        if (preset.preset == name) return &preset;
    }
    return nullptr;
}

std::vector<std::string_view> medium_preset_names() {
    std::vector<std::string_view> names;
    for (const Medium& preset : kPresets) names.push_back(preset.preset);
    return names;
}

Medium default_medium() { return *find_medium_preset("pure"); }

}  // namespace vkw
