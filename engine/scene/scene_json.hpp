// The scene schema: JSON (already parsed and overridden) to a validated Scene. One reader
// function per section, each over a FieldReader; a new section (water, waves, medium, ...)
// is a new function here and one line in scene_from_json.
#pragma once

#include <filesystem>

#include <nlohmann/json.hpp>

#include "engine/scene/error_context.hpp"
#include "engine/scene/field_reader.hpp"
#include "engine/scene/scene.hpp"

namespace vkw {

Scene scene_from_json(const nlohmann::json& root, const ErrorContext& errors, const std::filesystem::path& source);

Camera read_camera(FieldReader& fields);      // camera_json.cpp
Sun read_sun(FieldReader& fields);            // light_json.cpp
Sky read_sky(FieldReader& fields);            // light_json.cpp
FloorPlane read_floor(FieldReader& fields);   // floor_json.cpp

}  // namespace vkw
