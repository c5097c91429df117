// The top level of the scene schema (see scene_json.hpp and scenes/README.md).
#include "engine/scene/scene_json.hpp"

namespace vkw {

Scene scene_from_json(const nlohmann::json& root, const ErrorContext& errors, const std::filesystem::path& source) {
    if (!root.is_object()) {
        errors.fail("", "expected a JSON object, got " + describe_value(root), "an object with camera, sun, sky, floor");
    }
    FieldReader fields(root, "", errors);
    Scene scene;
    scene.source = source;
    scene.description = fields.string("description", "");
    scene.camera = fields.object("camera", Presence::required, read_camera);
    scene.sun = fields.object("sun", Presence::required, read_sun);
    scene.sky = fields.object("sky", Presence::required, read_sky);
    scene.floor = fields.object("floor", Presence::optional, read_floor);
    fields.finish();
    return scene;
}

}  // namespace vkw
