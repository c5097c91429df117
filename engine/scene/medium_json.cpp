// The "medium" section of the scene schema: a named preset (medium.cpp, docs/model.md section 1)
// or explicit coefficients, never both.
#include "engine/scene/scene_json.hpp"

namespace vkw {
namespace {

std::string forms(const std::vector<std::string_view>& presets) {
    return "either preset (" + one_of(presets) + "), or sigma_a and sigma_s with optional g";
}

}  // namespace

Medium read_medium(FieldReader& fields) {
    const std::vector<std::string_view> presets = medium_preset_names();
    const auto preset = fields.optional_choice_index("preset", presets);
    const auto sigma_a = fields.optional_vec3("sigma_a", Range::closed(0.0, kMaxCoefficient, "1/m"));
    const auto sigma_s = fields.optional_vec3("sigma_s", Range::closed(0.0, kMaxCoefficient, "1/m"));
    const auto g = fields.optional_number("g", Range::open(-1.0, 1.0));
    fields.finish();

    const bool coefficients = sigma_a || sigma_s || g;
    if (preset && coefficients) fields.fail("", "both preset and sigma_a/sigma_s/g are given", forms(presets));
    if (preset) return *find_medium_preset(presets[*preset]);
    if (!coefficients) return default_medium();
    // A partial set would have to borrow the rest from some preset: ask for it instead.
    if (!sigma_a) fields.fail("sigma_a", "missing (sigma_s or g is given)", forms(presets));
    if (!sigma_s) fields.fail("sigma_s", "missing (sigma_a is given)", forms(presets));
    return Medium{.preset = "", .sigma_a = *sigma_a, .sigma_s = *sigma_s, .g = g.value_or(0.0)};
}

}  // namespace vkw
