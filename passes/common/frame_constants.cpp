#include "passes/common/frame_constants.hpp"

#include "engine/scene/receiver_boxes.hpp"

#include <cmath>
#include <cstdlib>

namespace vkw {

FrameConstants make_frame_constants(const Scene& scene, uint32_t width, uint32_t height) {
    const double aspect = static_cast<double>(width) / static_cast<double>(height);
    const glm::dmat4 view_proj = projection_matrix(scene.camera, aspect) * view_matrix(scene.camera);
    FrameConstants constants{};
    constants.view_proj = glm::mat4(view_proj);
    constants.inv_view_proj = glm::mat4(glm::inverse(view_proj));
    constants.camera_position = glm::vec4(glm::vec3(scene.camera.position), 1.0f);
    const bool sun_up = scene.sun.direction.y < 0.0;
    constants.sun_direction = glm::vec4(glm::vec3(scene.sun.direction), sun_up ? 1.0f : 0.0f);
    constants.sun_irradiance = glm::vec4(glm::vec3(scene.sun.irradiance), 0.0f);
    constants.sky_radiance = glm::vec4(glm::vec3(scene.sky.radiance), 0.0f);
    constants.sky_zenith = glm::vec4(glm::vec3(scene.sky.zenith), 0.0f);
    constants.sky_horizon = glm::vec4(glm::vec3(scene.sky.horizon), 0.0f);
    constants.sky_ground = glm::vec4(glm::vec3(scene.sky.ground), 0.0f);
    constants.sky_params = glm::vec4(scene.sky.model == SkyModel::Gradient ? 1.0f : 0.0f,
                                     static_cast<float>(scene.sky.exponent), 0.0f, 0.0f);
    constants.sky_average = glm::vec4(glm::vec3(sky_average_radiance(scene.sky)), 0.0f);
    constants.sun_disk = glm::vec4(static_cast<float>(std::cos(glm::radians(kSunDiskAngularRadiusDeg))),
                                   static_cast<float>(kSunDiskSolidAngle), 0.0f, 0.0f);
    const std::optional<FloorTiles>& tiles = scene.floor.tiles;
    constants.floor_plane =
        glm::vec4(static_cast<float>(scene.floor.height), static_cast<float>(scene.floor.half_extent),
                  tiles ? static_cast<float>(tiles->side) : 0.0f, tiles ? static_cast<float>(tiles->grout) : 0.0f);
    constants.floor_albedo = glm::vec4(glm::vec3(scene.floor.albedo), 0.0f);
    constants.floor_grout = glm::vec4(tiles ? glm::vec3(tiles->grout_albedo) : glm::vec3(0.0f), 0.0f);
    constants.camera_near = glm::vec4(static_cast<float>(scene.camera.near_plane), 0.0f, 0.0f, 0.0f);
    constants.viewport = glm::vec4(static_cast<float>(width), static_cast<float>(height), 0.0f, 0.0f);
    constants.medium_sigma_t = glm::vec4(glm::vec3(scene.medium.sigma_t()), 0.0f);
    constants.medium_sigma_s = glm::vec4(glm::vec3(scene.medium.sigma_s), static_cast<float>(scene.medium.g));
    constants.medium_options = glm::vec4(1.0f, 0.0f, 0.0f, 0.0f);  // the renderer clears x when godrays run
    const ReceiverBoxes boxes = receiver_boxes(scene);
    constants.receiver_boxes = glm::vec4(static_cast<float>(boxes.count), 0.0f, 0.0f, 0.0f);
    for (std::size_t i = 0; i < boxes.count; ++i) {
        constants.receiver_box_min[i] = glm::vec4(glm::vec3(boxes.lo[i]), 0.0f);
        constants.receiver_box_max[i] = glm::vec4(glm::vec3(boxes.hi[i]), 0.0f);
    }
    if (scene.water) {
        const Water& water = *scene.water;
        constants.water = glm::vec4(static_cast<float>(water.level), static_cast<float>(water.ior),
                                    static_cast<float>(water.half_extent), 1.0f);
        // The fallback for frames whose camera-medium split is culled (passes/water/camera_medium.hpp
        // classifies every pixel otherwise).
        constants.camera_medium = glm::vec4(camera_eye_in_water(scene) ? 1.0f : 0.0f, 0.0f, 0.0f, 0.0f);
        if (water.infinite) {
            // Where a camera ray in the water that meets nothing ends (shaders/sky/sky.frag).
            constants.camera_medium.y = static_cast<float>(water_bottom(scene));
            constants.camera_medium.z = static_cast<float>(kInfiniteWaterFarField);
        }
        // Only the glitter reads the table (its shader variant); without it the fields stay 0.
        if (scene.effects.water.glitter) {
            const UnresolvedSlopeTable slopes = unresolved_slope_table(water.waves);
            constants.glitter = glm::vec4(static_cast<float>(slopes.log_k0), static_cast<float>(slopes.log_step),
                                          slopes.any ? 1.0f : 0.0f, static_cast<float>(slopes.total_variance));
            for (std::size_t i = 0; i < kUnresolvedSlopeEntries; ++i) {
                constants.unresolved_slopes[i] = slopes.entries[i];
            }
        }
    }
    return constants;
}

bool camera_eye_in_water(const Scene& scene) {
    if (!scene.water) return false;
    const Water& water = *scene.water;
    const glm::dvec3 eye = scene.camera.position;
    const double extent = water_drawn_half_extent(scene);
    return eye.y < water.level && eye.y >= water_bottom(scene) && std::abs(eye.x) <= extent &&
           std::abs(eye.z) <= extent;
}

}  // namespace vkw
