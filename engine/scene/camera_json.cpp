// The "camera" section of the scene schema.
#include <glm/glm.hpp>

#include "engine/scene/scene_json.hpp"

namespace vkw {
namespace {

// Closer than this, target - position has no usable direction.
constexpr double kMinTargetDistance = 1e-6;

}  // namespace

Camera read_camera(FieldReader& fields) {
    const Camera defaults;
    Camera camera;
    camera.position = fields.vec3("position", Range::any("m"));
    camera.target = fields.vec3("target", Range::any("m"));
    camera.fov_y_deg = fields.number("fov_y_deg", Range::open(1.0, 179.0, "degrees"), defaults.fov_y_deg);
    camera.near_plane = fields.number("near", Range::above(0.0, "m"), defaults.near_plane);
    camera.far_plane = fields.number("far", Range::above(0.0, "m"), defaults.far_plane);
    camera.exposure = fields.number("exposure", Range::above(0.0), defaults.exposure);
    fields.finish();

    if (!(camera.near_plane < camera.far_plane)) {
        // Say so when far was not written: "far: 500" would puzzle someone who only set near.
        const std::string far_text = format_number(camera.far_plane) + (fields.has("far") ? "" : " (the default)");
        fields.fail("far", far_text + " is not greater than " + fields.path_of("near") + " = " +
                               format_number(camera.near_plane),
                    "value > " + fields.path_of("near"));
    }
    if (glm::length(camera.target - camera.position) < kMinTargetDistance) {
        fields.fail("target", format_vec3(camera.target) + " coincides with " + fields.path_of("position"),
                    "a point at least " + format_number(kMinTargetDistance) + " m from " + fields.path_of("position"));
    }
    return camera;
}

}  // namespace vkw
