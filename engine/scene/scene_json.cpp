// The top level of the scene schema (see scene_json.hpp and scenes/README.md).
#include "engine/scene/scene_json.hpp"

namespace vkw {

Scene scene_from_json(const nlohmann::json& root, const ErrorContext& errors, const std::filesystem::path& source,
                      const FileScope& scope) {
    if (!root.is_object()) {
        errors.fail("", "expected a JSON object, got " + describe_value(root),
                    "an object with camera, sun, sky and optional floor, water, medium, receivers, effects");
    }
    FieldReader fields(root, "", errors);
    Scene scene;
    scene.source = source;
    scene.description = fields.string("description", "");
    scene.camera = fields.object("camera", Presence::required, read_camera);
    scene.sun = fields.object("sun", Presence::required, read_sun);
    scene.sky = fields.object("sky", Presence::required, read_sky);
    scene.floor = fields.object("floor", Presence::optional, read_floor);
    // Absent water means no water, not default water.
    if (fields.has("water")) scene.water = fields.object("water", Presence::required, read_water);
    scene.medium = fields.object("medium", Presence::optional, read_medium);
    scene.receivers =
        fields.objects("receivers", [&](FieldReader& receiver) { return read_receiver(receiver, scope); });
    scene.effects = fields.object("effects", Presence::optional, read_effects);
    fields.finish();
    if (scene.water && scene.water->infinite) scene.water->half_extent = receivers_half_extent(scene);

    if (scene.water && !scene.water->depth && !(scene.floor.height < scene.water->level)) {
        errors.fail("water.level",
                    format_number(scene.water->level) + " is not above floor.height = " +
                        format_number(scene.floor.height) + ", so the water has no volume",
                    "value > floor.height, or water.depth to give the volume its own bottom");
    }
    return scene;
}

}  // namespace vkw
