// Quantities derived from the scene description: sun angles to a direction, the view matrix,
// the sky's radiance and the bottom of the water.
#include "engine/scene/scene.hpp"

#include <algorithm>
#include <cmath>

#include <glm/gtc/matrix_transform.hpp>

#include "engine/scene/angles.hpp"

namespace vkw {

std::vector<MeshPart> receiver_albedo_parts(const Receiver& receiver) {
    if (!receiver.mesh.parts.empty()) return receiver.mesh.parts;
    return {{0, static_cast<uint32_t>(receiver.mesh.indices.size()), receiver.albedo}};
}

uint32_t Water::drawn_mesh_resolution() const {
    return mesh_resolution.value_or(std::min(kDefaultWaterMeshResolution, grid_resolution));
}

uint32_t Water::screen_mesh_cell_pixels() const {
    if (mesh_resolution) return 0;
    return mesh_cell_pixels.value_or(infinite ? kDefaultInfiniteWaterCellPixels : 0);
}

glm::dvec3 direction_toward_sun(double elevation_deg, double azimuth_deg) {
    double sin_el = 0.0, cos_el = 0.0, sin_az = 0.0, cos_az = 0.0;
    sin_cos_deg(elevation_deg, sin_el, cos_el);
    sin_cos_deg(azimuth_deg, sin_az, cos_az);
    return {cos_el * sin_az, sin_el, -cos_el * cos_az};
}

glm::dmat4 view_matrix(const Camera& camera) {
    const glm::dvec3 dir = glm::normalize(camera.target - camera.position);
    // Near vertical, cross(dir, +y) degenerates and the image would spin about the view
    // axis; there |dir.z| < 0.045, so -z is safely far from parallel to dir.
    const glm::dvec3 up = std::abs(dir.y) > 0.999 ? glm::dvec3(0.0, 0.0, -1.0) : glm::dvec3(0.0, 1.0, 0.0);
    return glm::lookAtRH(camera.position, camera.target, up);
}

glm::dvec3 sky_radiance(const Sky& sky, const glm::dvec3& dir) {
    if (sky.model == SkyModel::Constant) return sky.radiance;
    if (dir.y < 0.0) return sky.ground;
    return glm::mix(sky.horizon, sky.zenith, std::pow(dir.y, sky.exponent));
}

glm::dvec3 sky_average_radiance(const Sky& sky) {
    if (sky.model == SkyModel::Constant) return sky.radiance;
    // (1/pi) int_0^2pi int_0^1 mix(h, z, mu^e) mu dmu dphi = h + (z - h) * 2 int_0^1 mu^(e+1) dmu.
    return sky.horizon + (sky.zenith - sky.horizon) * (2.0 / (sky.exponent + 2.0));
}

double water_bottom(const Scene& scene) {
    if (scene.water && scene.water->depth) return scene.water->level - *scene.water->depth;
    return scene.floor.height;
}

double water_drawn_half_extent(const Scene& scene) {
    const Water& water = *scene.water;
    if (!water.infinite) return water.half_extent;
    const glm::dvec3& eye = scene.camera.position;
    return std::max(std::abs(eye.x), std::abs(eye.z)) + scene.camera.far_plane;
}

double receivers_half_extent(const Scene& scene) {
    double extent = scene.floor.half_extent;
    for (const Receiver& receiver : scene.receivers) {
        if (receiver.mesh.positions.empty()) continue;
        const glm::dvec3 lo = receiver.mesh.bounds_min, hi = receiver.mesh.bounds_max;
        extent = std::max({extent, std::abs(lo.x), std::abs(lo.z), std::abs(hi.x), std::abs(hi.z)});
    }
    return extent;
}

glm::dmat4 projection_matrix(const Camera& camera, double aspect) {
    // Swapping near and far in a [0, 1]-depth projection gives reversed-Z, which
    // spends float precision where perspective depth needs it.
    const glm::dmat4 projection =
        glm::perspectiveRH_ZO(glm::radians(camera.fov_y_deg), aspect, camera.far_plane, camera.near_plane);
    if (camera.image_shift_ndc == glm::dvec2(0.0)) return projection;
    glm::dmat4 shift(1.0);
    shift[3] = glm::dvec4(camera.image_shift_ndc, 0.0, 1.0);
    return shift * projection;
}

uint32_t terrain_cells(const TerrainShape& shape, double fraction) {
    return std::max<uint32_t>(2, static_cast<uint32_t>(std::lround(shape.resolution * fraction)));
}

void set_terrain_detail(Receiver& receiver, double fraction) {
    if (!receiver.terrain) return;
    TerrainShape shape = *receiver.terrain;
    shape.resolution = terrain_cells(shape, fraction);
    const size_t vertices = size_t(shape.resolution + 1) * (shape.resolution + 1);
    if (receiver.mesh.positions.size() == vertices) return;
    receiver.mesh = make_terrain_mesh(shape);
    transform_mesh(receiver.mesh, receiver.object_to_world);
}

std::vector<std::string> scene_warnings(const Scene& scene) {
    std::vector<std::string> warnings;
    for (const Receiver& receiver : scene.receivers) {
        warnings.insert(warnings.end(), receiver.mesh.warnings.begin(), receiver.mesh.warnings.end());
    }
    return warnings;
}

}  // namespace vkw
