// Loading a scene file (JSON, schema in scenes/README.md) into a validated Scene.
//
// Every problem with the file or an override throws vkw::UserError with one line:
//   <file>: <field path>: <what> (accepted: <range>)
// e.g. "scenes/pool.json: camera.fov_y_deg: 0 is out of range (accepted: 1 < value < 179 degrees)".
#pragma once

#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

#include "engine/scene/scene.hpp"

namespace vkw {

struct SceneLoadOptions {
    // Files the scene names (glTF receivers, and the buffers and images those name) are read only
    // inside the scene file's folder tree unless this is set (the CLI's --allow-outside-paths).
    bool allow_outside_paths = false;
};

// Reads, parses, overrides and validates `file`. Each override is "key.path=value" (the CLI's
// --set), e.g. "camera.fov_y_deg=75" or "sun.irradiance=[2,2,2]": the value is parsed as JSON,
// or taken as a string when it is not JSON; the value null removes the field. Overrides are
// applied in order to the JSON before validation, so an override of an unknown key is refused
// exactly like an unknown field in the file.
Scene load_scene(const std::filesystem::path& file, const std::vector<std::string>& overrides = {},
                 const SceneLoadOptions& options = {});

// The same from text in memory; `name_for_messages` stands in for the file name in errors
// and becomes Scene::source, and glTF receivers' files are resolved against its folder.
Scene parse_scene(std::string_view json_text, const std::filesystem::path& name_for_messages,
                  const std::vector<std::string>& overrides = {}, const SceneLoadOptions& options = {});

}  // namespace vkw
