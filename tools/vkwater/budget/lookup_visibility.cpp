// The scene lookups' share of the frame's light (lookup_visibility.hpp).
#include "tools/vkwater/budget/lookup_visibility.hpp"

#include "tools/reference/bvh.hpp"
#include "tools/reference/optics.hpp"
#include "tools/reference/reference_renderer.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

namespace vkw::budget {
namespace {

constexpr double kFar = 1e9;  // m: beyond every scene

// How far along `ray` it meets the floor's square, or kFar.
double floor_distance(const FloorPlane& floor, const ref::Ray& ray) {
    if (!(ray.direction.y < 0.0) || ray.origin.y < floor.height) return kFar;
    const double t = (floor.height - ray.origin.y) / ray.direction.y;
    const glm::dvec3 at = ray.origin + t * ray.direction;
    return std::abs(at.x) <= floor.half_extent && std::abs(at.z) <= floor.half_extent ? t : kFar;
}

}  // namespace

LookupVisibility lookup_visibility(const Scene& scene, double aspect) {
    LookupVisibility visibility;
    if (!scene.water || scene.receivers.empty()) return visibility;
    const Water& water = *scene.water;
    std::vector<const Mesh*> meshes;
    for (const Receiver& receiver : scene.receivers) meshes.push_back(&receiver.mesh);
    const ref::TriangleBvh bvh(meshes);
    const glm::dvec3 sigma_t = scene.medium.sigma_t();
    const double sigma = std::min({sigma_t.r, sigma_t.g, sigma_t.b});
    const bool camera_in_water = scene.camera.position.y < water.level;
    const double n_camera = camera_in_water ? water.ior : 1.0, n_other = camera_in_water ? 1.0 : water.ior;
    // A ray's weight where it meets a receiver before the floor (0 where it meets none), the
    // medium's transmittance along it where it runs in the water.
    const auto weight_along = [&](const ref::Ray& ray, double fresnel, bool in_water) {
        const std::optional<ref::TriangleHit> hit = bvh.closest_hit(ray, floor_distance(scene.floor, ray));
        if (!hit) return 0.0;
        return fresnel * (in_water ? std::exp(-sigma * hit->distance) : 1.0);
    };
    const uint32_t rows = kLookupVisibilityRows;
    const auto columns = std::max<uint32_t>(1, static_cast<uint32_t>(std::lround(rows * aspect)));
    for (uint32_t y = 0; y < rows; ++y) {
        for (uint32_t x = 0; x < columns; ++x) {
            const ref::Ray ray = ref::camera_ray(scene.camera, columns, rows, x + 0.5, y + 0.5);
            // Where the camera ray meets the flat surface, if nothing hides it there.
            const double t = (water.level - ray.origin.y) / ray.direction.y;
            if (!(t > 0.0) || !std::isfinite(t)) continue;
            const glm::dvec3 p = ray.origin + t * ray.direction;
            if (!water.infinite && (std::abs(p.x) > water.half_extent || std::abs(p.z) > water.half_extent)) continue;
            if (bvh.any_hit(ray, t)) continue;
            const glm::dvec3 normal{0.0, camera_in_water ? -1.0 : 1.0, 0.0};  // on the camera's side
            const double cos_i = std::abs(ray.direction.y);
            const double reflectance = ref::fresnel_reflectance(cos_i, n_camera, n_other);
            const glm::dvec3 reflected{ray.direction.x, -ray.direction.y, ray.direction.z};
            visibility.reflection += weight_along({p, reflected}, reflectance, camera_in_water);
            if (const std::optional<glm::dvec3> refracted = ref::refract(ray.direction, normal, n_camera / n_other)) {
                visibility.refraction += weight_along({p, *refracted}, 1.0 - reflectance, !camera_in_water);
            }
        }
    }
    const double samples = double(rows) * columns;
    visibility.reflection /= samples;
    visibility.refraction /= samples;
    return visibility;
}

}  // namespace vkw::budget
