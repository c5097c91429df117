#include "tools/reference/flat_water_transport.hpp"

#include "engine/core/errors.hpp"
#include "engine/scene/builtin_meshes.hpp"
#include "tools/reference/optics.hpp"

#include <glm/gtc/matrix_transform.hpp>

#include <cmath>
#include <limits>
#include <numbers>

namespace vkw::ref {
namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();
// Ray origins are pushed off the surface they leave by this much (metres): far above
// double rounding at scene scale (1e-15 * 1e3 m), far below any feature of a scene.
constexpr double kOffset = 1e-9;
constexpr double kSunDiskSolidAngle = 6.80e-5;       // PHYSICS.md section 1
constexpr double kSunDiskAngularRadiusDeg = 0.2666;

glm::dvec3 exp3(const glm::dvec3& x) { return {std::exp(x.x), std::exp(x.y), std::exp(x.z)}; }

}  // namespace

FlatWaterTransport::FlatWaterTransport(const Scene& scene) : scene_(scene) {
    if (scene.water && scene.water->waves.model != WaveModel::Flat) {
        throw UserError(scene.source.string() +
                        ": water.waves.model: the reference renderer computes flat water only so far; wavy "
                        "surfaces need its caustic beam mapping, not built yet (accepted now: \"flat\")");
    }
    // The floor joins the receivers as one more mesh.
    Mesh floor = make_plane_mesh({scene.floor.half_extent, scene.floor.half_extent});
    transform_mesh(floor, glm::translate(glm::dmat4(1.0), glm::dvec3(0.0, scene.floor.height, 0.0)));
    extra_meshes_.push_back(std::move(floor));
    std::vector<const Mesh*> meshes{&extra_meshes_[0]};
    albedo_.push_back(scene.floor.albedo);
    for (const Receiver& receiver : scene.receivers) {
        meshes.push_back(&receiver.mesh);
        albedo_.push_back(receiver.albedo * glm::dvec3(receiver.mesh.base_color));
    }
    bvh_ = std::make_unique<TriangleBvh>(meshes);

    has_water_ = scene.water.has_value();
    if (has_water_) {
        level_ = scene.water->level;
        half_extent_ = scene.water->half_extent;
        bottom_ = water_bottom(scene);
        ior_ = scene.water->ior;
    }
    sun_up_ = scene.sun.direction.y < 0.0;
    const double cos_s = -scene.sun.direction.y;
    if (sun_up_) {
        refracted_sun_ = *refract(scene.sun.direction, {0.0, 1.0, 0.0}, 1.0 / ior_);  // never TIR from air
        const double cos_t = -refracted_sun_.y;
        const double transmittance = 1.0 - fresnel_reflectance(cos_s, 1.0, ior_);
        e_perp0_ = scene.sun.irradiance * (cos_s * transmittance / cos_t);
    }
    sky_average_ = sky_average_radiance(scene.sky);
    hemispherical_transmittance_ = hemispherical_transmittance(ior_);
    sun_disk_cos_ = std::cos(kSunDiskAngularRadiusDeg * std::numbers::pi / 180.0);
}

bool FlatWaterTransport::in_water(const glm::dvec3& p) const {
    // Height exactly at the level counts as above (the same tie-break as the stencil
    // split). The bottom is usually the floor itself, and a floor hit can round a hair
    // below it: points within kBottomTolerance of the bottom are in the water.
    constexpr double kBottomTolerance = 1e-6;
    return has_water_ && p.y < level_ && p.y >= bottom_ - kBottomTolerance && std::abs(p.x) <= half_extent_ &&
           std::abs(p.z) <= half_extent_;
}

std::optional<FlatWaterTransport::SurfaceHit> FlatWaterTransport::closest_receiver(const Ray& ray,
                                                                                    double max_distance) const {
    const auto hit = bvh_->closest_hit(ray, max_distance);
    if (!hit) return std::nullopt;
    return SurfaceHit{hit->distance, albedo_[hit->receiver], hit->normal};
}

bool FlatWaterTransport::sun_blocked_in_air(const glm::dvec3& point) const {
    return bvh_->any_hit({point, -scene_.sun.direction}, kInfinity);
}

glm::dvec3 FlatWaterTransport::sun_irradiance_under_water(const glm::dvec3& point, const glm::dvec3& normal) const {
    if (!sun_up_) return glm::dvec3(0.0);
    const double cos_receiver = std::max(0.0, -glm::dot(refracted_sun_, normal));
    if (cos_receiver == 0.0) return glm::dvec3(0.0);
    // Shadowed along the refracted beam by objects under the water, then along the
    // sun's direction by objects above it.
    const double path = (level_ - point.y) / -refracted_sun_.y;
    const Ray up{point + kOffset * normal, -refracted_sun_};
    if (bvh_->any_hit(up, path)) return glm::dvec3(0.0);
    const glm::dvec3 entry = point - path * refracted_sun_;
    if (sun_blocked_in_air(entry + glm::dvec3(0.0, kOffset, 0.0))) return glm::dvec3(0.0);
    return e_perp0_ * cos_receiver * exp3(-scene_.medium.sigma_t() * path);
}

glm::dvec3 FlatWaterTransport::receiver_radiance(const glm::dvec3& point, const SurfaceHit& hit,
                                                 glm::dvec3* caustic) const {
    glm::dvec3 irradiance;
    if (in_water(point)) {
        const glm::dvec3 sun = sun_irradiance_under_water(point, hit.normal);
        if (caustic) *caustic = sun;
        const double depth = level_ - point.y;
        irradiance = sun + std::numbers::pi * sky_average_ * hemispherical_transmittance_ *
                               exp3(-scene_.medium.sigma_t() * depth);
    } else {
        glm::dvec3 sun(0.0);
        if (sun_up_) {
            const double cos_sun = std::max(0.0, -glm::dot(scene_.sun.direction, hit.normal));
            if (cos_sun > 0.0 && !sun_blocked_in_air(point + kOffset * hit.normal)) sun = scene_.sun.irradiance * cos_sun;
        }
        irradiance = sun + std::numbers::pi * sky_average_;
    }
    return hit.albedo * irradiance / std::numbers::pi;
}

glm::dvec3 FlatWaterTransport::radiance_in_air(const Ray& ray) const {
    if (const auto hit = closest_receiver(ray, kInfinity)) {
        return receiver_radiance(ray.origin + hit->distance * ray.direction, *hit, nullptr);
    }
    glm::dvec3 radiance = sky_radiance(scene_.sky, ray.direction);
    if (sun_up_ && glm::dot(ray.direction, -scene_.sun.direction) >= sun_disk_cos_) {
        radiance += scene_.sun.irradiance / kSunDiskSolidAngle;
    }
    return radiance;
}

glm::dvec3 FlatWaterTransport::in_water_segment(double z0, double length, const glm::dvec3& direction,
                                                const glm::dvec3& behind) const {
    glm::dvec3 radiance;
    const glm::dvec3 sigma_t = scene_.medium.sigma_t();
    for (int c = 0; c < 3; ++c) {
        InScatterInput in{scene_.medium.sigma_s[c], sigma_t[c], scene_.medium.g, z0, length, direction,
                          refracted_sun_, sun_up_ ? e_perp0_[c] : 0.0, behind[c]};
        radiance[c] = water_path_radiance(in);
    }
    return radiance;
}

glm::dvec3 FlatWaterTransport::radiance_in_water_to_receiver(const Ray& ray, glm::dvec3* caustic) const {
    const auto hit = closest_receiver(ray, kInfinity);
    // A ray that leaves the water body without meeting a receiver sees nothing (the
    // scenes close their water with a floor or walls).
    const double length = hit ? hit->distance : 0.0;
    const glm::dvec3 behind =
        hit ? receiver_radiance(ray.origin + hit->distance * ray.direction, *hit, caustic) : glm::dvec3(0.0);
    return in_water_segment(level_ - ray.origin.y, length, ray.direction, behind);
}

PixelRadiance FlatWaterTransport::trace_camera_ray(const Ray& ray) const {
    PixelRadiance pixel;
    const bool camera_in_water = in_water(ray.origin);
    // Where the ray meets the water's surface, if it does within the water's extent.
    double to_surface = kInfinity;
    if (has_water_ && ray.direction.y != 0.0) {
        const double t = (level_ - ray.origin.y) / ray.direction.y;
        const glm::dvec3 p = ray.origin + t * ray.direction;
        if (t > 0.0 && std::abs(p.x) <= half_extent_ && std::abs(p.z) <= half_extent_) to_surface = t;
    }
    const auto receiver = closest_receiver(ray, to_surface);

    if (!camera_in_water) {
        if (receiver || to_surface == kInfinity) {  // nothing but air on the way
            if (receiver) {
                pixel.radiance = receiver_radiance(ray.origin + receiver->distance * ray.direction, *receiver,
                                                   &pixel.caustic);
            } else {
                pixel.radiance = radiance_in_air(ray);
            }
            return pixel;
        }
        // The surface from above: reflect into the air, refract into the water.
        const glm::dvec3 p = ray.origin + to_surface * ray.direction;
        const glm::dvec3 up{0.0, 1.0, 0.0};
        const double cos_i = -ray.direction.y;
        const double reflectance = fresnel_reflectance(cos_i, 1.0, ior_);
        const glm::dvec3 reflected = glm::reflect(ray.direction, up);
        const glm::dvec3 l_reflected = radiance_in_air({p + kOffset * up, reflected});
        const glm::dvec3 refracted = *refract(ray.direction, up, 1.0 / ior_);
        const glm::dvec3 l_water = radiance_in_water_to_receiver({p - kOffset * up, refracted}, &pixel.caustic);
        pixel.radiance = reflectance * l_reflected + (1.0 - reflectance) / (ior_ * ior_) * l_water;
        return pixel;
    }

    // Camera in the water.
    const double z0 = level_ - ray.origin.y;
    if (receiver) {
        const glm::dvec3 behind =
            receiver_radiance(ray.origin + receiver->distance * ray.direction, *receiver, &pixel.caustic);
        pixel.radiance = in_water_segment(z0, receiver->distance, ray.direction, behind);
        return pixel;
    }
    if (to_surface == kInfinity) {
        pixel.radiance = in_water_segment(z0, 0.0, ray.direction, glm::dvec3(0.0));
        return pixel;
    }
    // The surface from below: Snell's window, total internal reflection outside it.
    const glm::dvec3 p = ray.origin + to_surface * ray.direction;
    const glm::dvec3 down{0.0, -1.0, 0.0};
    const double cos_i = ray.direction.y;
    const double reflectance = fresnel_reflectance(cos_i, ior_, 1.0);
    glm::dvec3 at_surface =
        reflectance * radiance_in_water_to_receiver({p + kOffset * down, glm::reflect(ray.direction, down)}, nullptr);
    if (const auto refracted = refract(ray.direction, down, ior_)) {
        at_surface += (1.0 - reflectance) * ior_ * ior_ * radiance_in_air({p - kOffset * down, *refracted});
    }
    pixel.radiance = in_water_segment(z0, to_surface, ray.direction, at_surface);
    return pixel;
}

}  // namespace vkw::ref
