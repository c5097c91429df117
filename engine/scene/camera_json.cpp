// The "camera" section of the scene schema. The view has two exclusive forms: target (a point
// looked at) or direction (a view vector, normalised here; target = position + direction).
#include <glm/glm.hpp>

#include "engine/scene/direction.hpp"
#include "engine/scene/scene_json.hpp"

namespace vkw {
namespace {

// Closer than this, target - position has no usable direction.
constexpr double kMinTargetDistance = 1e-6;

constexpr std::string_view kViewForms = "exactly one of target, direction";

}  // namespace

Camera read_camera(FieldReader& fields) {
    const Camera defaults;
    Camera camera;
    camera.position = fields.vec3("position", Range::length());
    const auto target = fields.optional_vec3("target", Range::length());
    const auto direction = fields.optional_vec3("direction", Range::any());
    camera.fov_y_deg = fields.number("fov_y_deg", Range::open(1.0, 179.0, "degrees"), defaults.fov_y_deg);
    camera.near_plane = fields.number("near", Range::positive_length(), defaults.near_plane);
    camera.far_plane = fields.number("far", Range::positive_length(), defaults.far_plane);
    camera.exposure =
        fields.number("exposure", Range{.min = 0.0, .max = kMaxRadiometric, .min_inclusive = false}, defaults.exposure);
    fields.finish();

    if (!(camera.near_plane < camera.far_plane)) {
        // Say so when far was not written: "far: 500" would puzzle someone who only set near.
        const std::string far_text = format_number(camera.far_plane) + (fields.has("far") ? "" : " (the default)");
        fields.fail(
            "far",
            far_text + " is not greater than " + fields.path_of("near") + " = " + format_number(camera.near_plane),
            "value > " + fields.path_of("near"));
    }
    if (target && direction) fields.fail("", "both target and direction are given", kViewForms);
    if (!target && !direction) {
        fields.fail("target", "missing required field", "an array of 3 finite numbers, in m; or direction instead");
    }
    if (direction) {
        const auto unit = unit_direction(*direction);
        if (!unit) fields.fail("direction", "[0, 0, 0] has no direction", "a non-zero vector");
        camera.target = camera.position + *unit;
        return camera;
    }
    camera.target = *target;
    if (glm::length(camera.target - camera.position) < kMinTargetDistance) {
        fields.fail("target", format_vec3(camera.target) + " coincides with " + fields.path_of("position"),
                    "a point at least " + format_number(kMinTargetDistance) + " m from " + fields.path_of("position"));
    }
    return camera;
}

}  // namespace vkw
