// The scene schema: JSON (already parsed and overridden) to a validated Scene. One reader
// function per section, each over a FieldReader; a new section is a new function here and one
// line in scene_from_json.
#pragma once

#include <filesystem>

#include <nlohmann/json.hpp>

#include "engine/scene/error_context.hpp"
#include "engine/scene/field_reader.hpp"
#include "engine/scene/file_scope.hpp"
#include "engine/scene/scene.hpp"

namespace vkw {

// `scope`: where the files the scene names may be, and the folder they are relative to.
Scene scene_from_json(const nlohmann::json& root, const ErrorContext& errors, const std::filesystem::path& source,
                      const FileScope& scope);

Camera read_camera(FieldReader& fields);                     // camera_json.cpp
Sun read_sun(FieldReader& fields);                           // light_json.cpp
Sky read_sky(FieldReader& fields);                           // light_json.cpp
FloorPlane read_floor(FieldReader& fields);                  // floor_json.cpp
Water read_water(FieldReader& fields);                       // water_json.cpp
WaveSettings read_waves(FieldReader& fields);                // waves_json.cpp
Medium read_medium(FieldReader& fields);                     // medium_json.cpp
EffectsSettings read_effects(FieldReader& fields);           // effects_json.cpp
GodraySettings read_godray_settings(FieldReader& fields);    // godrays_json.cpp: effects.godrays but its mode
CausticSettings read_caustic_settings(FieldReader& fields);  // caustics_json.cpp: effects.caustics but its mode
CausticBlurSettings read_caustic_blur_settings(
    FieldReader& fields);  // caustics_json.cpp: effects.caustic_blur but its mode
// glTF file names are resolved against `scope`'s folder, and must stay inside its tree.
Receiver read_receiver(FieldReader& fields, const FileScope& scope);  // receiver_json.cpp

}  // namespace vkw
