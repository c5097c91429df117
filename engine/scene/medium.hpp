// The water's optical properties (docs/model.md section 1, "Medium"): homogeneous absorption and
// scattering per RGB channel and a Henyey-Greenstein phase function, and the named presets.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include <glm/glm.hpp>

namespace vkw {

struct Medium {
    std::string preset;                 // the preset it came from; empty when given explicitly
    glm::dvec3 sigma_a{0.0, 0.0, 0.0};  // absorption, 1/m, >= 0
    glm::dvec3 sigma_s{0.0, 0.0, 0.0};  // scattering, 1/m, >= 0
    double g = 0.0;                     // Henyey-Greenstein parameter, in (-1, 1)

    glm::dvec3 sigma_t() const { return sigma_a + sigma_s; }  // extinction
};

// The preset of that name ("pure", "clear-ocean", "coastal", "turbid-harbour"), nullptr if none.
const Medium* find_medium_preset(std::string_view name);
std::vector<std::string_view> medium_preset_names();  // in table order

// The medium of a scene that states none: the "pure" preset.
Medium default_medium();

}  // namespace vkw
