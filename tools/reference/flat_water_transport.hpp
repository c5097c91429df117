// Light transport of the model (PHYSICS.md section 1) for a scene whose water surface
// is flat, computed exactly in double precision: view rays from the air or from the
// water, one reflection and one refraction at the surface (exact Fresnel, total
// internal reflection, radiance scaled by n^2 entering and 1/n^2 leaving), Lambertian
// receivers lit by the shadowed sun (through the surface under the water: the flat
// surface's refracted beam, which for flat water is the caustic irradiance itself) and
// by skylight, sigma_t attenuation and single scattering of the refracted sun beam.
#pragma once

#include "engine/scene/scene.hpp"
#include "tools/reference/bvh.hpp"

#include <glm/glm.hpp>

#include <memory>
#include <vector>

namespace vkw::ref {

struct PixelRadiance {
    glm::dvec3 radiance{0.0};
    glm::dvec3 caustic{0.0};  // sun irradiance on the receiver seen under the water, else 0
};

class FlatWaterTransport {
public:
    // Throws UserError when the scene needs what this class does not compute (waves).
    explicit FlatWaterTransport(const Scene& scene);

    PixelRadiance trace_camera_ray(const Ray& ray) const;

    // The model's quantities, exposed for tests.
    bool in_water(const glm::dvec3& point) const;
    glm::dvec3 sun_irradiance_under_water(const glm::dvec3& point, const glm::dvec3& normal) const;

private:
    struct SurfaceHit {
        double distance;
        glm::dvec3 albedo;
        glm::dvec3 normal;
    };
    std::optional<SurfaceHit> closest_receiver(const Ray& ray, double max_distance) const;
    // Radiance arriving along `ray` travelling in air (one surface event already spent
    // or none to come): receivers above the water, or the sky with the sun's disk.
    glm::dvec3 radiance_in_air(const Ray& ray) const;
    // Radiance of a Lambertian receiver point, in air or under the water.
    glm::dvec3 receiver_radiance(const glm::dvec3& point, const SurfaceHit& hit, glm::dvec3* caustic) const;
    // Radiance arriving at `start` along `ray` inside the water, up to the receiver it
    // meets (no surface event: the ray's one surface event is already spent).
    glm::dvec3 radiance_in_water_to_receiver(const Ray& ray, glm::dvec3* caustic) const;
    glm::dvec3 in_water_segment(double z0, double length, const glm::dvec3& direction,
                                const glm::dvec3& behind) const;
    bool sun_blocked_in_air(const glm::dvec3& point) const;

    const Scene& scene_;
    std::vector<Mesh> extra_meshes_;  // the floor as a mesh
    std::vector<glm::dvec3> albedo_;  // per receiver index of the BVH
    std::unique_ptr<TriangleBvh> bvh_;
    double level_ = 0.0, half_extent_ = 0.0, bottom_ = 0.0, ior_ = 1.0;
    bool has_water_ = false;
    bool sun_up_ = false;
    glm::dvec3 refracted_sun_{0.0, -1.0, 0.0};  // t, unit, downward
    glm::dvec3 e_perp0_{0.0};                   // E_s cos(theta_s) T / cos(theta_t), per channel
    glm::dvec3 sky_average_{0.0};
    double hemispherical_transmittance_ = 1.0;
    double sun_disk_cos_ = 1.0;
};

}  // namespace vkw::ref
