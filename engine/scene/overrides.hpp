// Applying "key.path=value" overrides (the CLI's --set) to a scene's JSON before validation.
#pragma once

#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "engine/scene/error_context.hpp"

namespace vkw {

// Applies each override in order. The value is parsed as JSON ("75", "[2,2,2]", "\"x\""), or
// taken as a string when it is not valid JSON ("pool", "nan"); null removes the field.
// Missing intermediate objects are created, so "floor.height=-2" works when the file has no
// floor. Array elements are addressed as "receivers[1].radius" or "sun.irradiance[0]"; the
// element must exist (arrays are not grown), and null removes it.
// Key names are not checked here: validation reports an unknown one like an unknown
// field, and `errors` remembers each override so that such a message names it.
// A root that is not an object is left alone for validation to report.
void apply_overrides(nlohmann::json& root, const std::vector<std::string>& overrides, ErrorContext& errors);

}  // namespace vkw
