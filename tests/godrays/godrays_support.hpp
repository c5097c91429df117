// Shared parts of the godray tests: small scenes of flat water with nothing but the in-scatter to
// see (sky 0, floor albedo 0), the GPU render, and the expected radiance of a camera ray from
// docs/model.md section 6 in double precision through the reference renderer's optics
// (tools/reference/optics.hpp, tested against the closed forms by tests/reference), which share
// nothing with the godray shaders but the equations.
#pragma once

#include "engine/scene/scene_loader.hpp"
#include "passes/frame/renderer.hpp"
#include "tools/reference/optics.hpp"
#include "tools/reference/reference_renderer.hpp"

#include <glm/glm.hpp>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

namespace vkw::test {

// Flat water 4 m either side of the origin, its beams cut at `max_depth` (far above the floor, which
// is black and too far for any test ray); a constant black sky; E_s = (1, 2, 3); the sun in the y-z
// plane, 60 degrees high, travelling toward +z. The camera and the medium come from the caller.
inline Scene godray_scene(const std::string& camera, const std::string& medium,
                          const std::vector<std::string>& overrides = {}) {
    return parse_scene(R"({
      "camera": )" + camera +
                           R"(,
      "sun": {"elevation_deg": 60, "azimuth_deg": 0, "irradiance": [1, 2, 3]},
      "sky": {"radiance": [0, 0, 0]},
      "floor": {"height": -50, "albedo": [0, 0, 0], "half_extent": 10},
      "water": {"level": 0, "ior": 1.333, "half_extent": 4, "grid_resolution": 8},
      "medium": )" + medium +
                           R"(,
      "effects": {"godrays": {"mode": "on", "resolution_scale": 1, "max_depth": 6}, "caustics": {"mode": "off"}}
    })",
                       "godrays_test.json", overrides);
}

inline RenderResult render_godrays(Context& context, const Scene& scene, uint32_t width, uint32_t height) {
    Renderer renderer(context);
    return renderer.render(scene, {width, height, true, fg::TimingMode::None});
}

// The part [s0, s1] of the ray o + s d (s >= 0) where the flat water is lit: under the surface,
// above max_depth, inside the water's square, and on a beam that entered the surface inside it.
// Empty (s1 <= s0) where it never is.
inline void lit_interval(const Scene& scene, const glm::dvec3& o, const glm::dvec3& d, const glm::dvec3& t, double& s0,
                         double& s1) {
    const double e = scene.water->half_extent, level = scene.water->level;
    const double deepest = level - scene.effects.godrays.max_depth.value_or(1e30);
    s0 = 0.0;
    s1 = 1e30;
    // Each bound is a . p <= b for p = o + s d.
    auto bound = [&](const glm::dvec3& a, double b) {
        const double at = glm::dot(a, o), rate = glm::dot(a, d);
        if (rate == 0.0) {
            if (at > b) s1 = -1.0;
            return;
        }
        const double s = (b - at) / rate;
        if (rate > 0.0)
            s1 = std::min(s1, s);
        else
            s0 = std::max(s0, s);
    };
    bound({0, 1, 0}, level);
    bound({0, -1, 0}, -deepest);
    // The beam through p entered at p - ((level - p.y) / -t.y) t, affine in p.
    const glm::dvec3 entry_x{1.0, -t.x / t.y, 0.0}, entry_z{0.0, -t.z / t.y, 1.0};
    const double entry_shift_x = level * t.x / t.y, entry_shift_z = level * t.z / t.y;
    for (const auto& [a, shift] : {std::pair{glm::dvec3(1, 0, 0), 0.0}, std::pair{glm::dvec3(0, 0, 1), 0.0},
                                   std::pair{entry_x, entry_shift_x}, std::pair{entry_z, entry_shift_z}}) {
        bound(a, e - shift);
        bound(-a, e + shift);
    }
}

// docs/model.md section 6: the in-scattered radiance of the flat beam seen along the camera ray d from
// the scene's eye, per channel: directly for a camera in the water, through the flat surface with
// T(theta_v) / n^2 from above. Nothing else lights these scenes.
inline glm::dvec3 expected_in_scatter(const Scene& scene, const glm::dvec3& d) {
    const double n = scene.water->ior, level = scene.water->level;
    const glm::dvec3 s = scene.sun.direction;
    const glm::dvec3 t = *ref::refract(s, {0.0, 1.0, 0.0}, 1.0 / n);
    const double cos_s = -s.y, cos_t = -t.y;
    const glm::dvec3 e_perp0 = scene.sun.irradiance * ((1.0 - ref::fresnel_reflectance(cos_s, 1.0, n)) * cos_s / cos_t);
    glm::dvec3 o = scene.camera.position, v = d;
    double weight = 1.0;
    if (o.y >= level) {  // from the air: through the flat surface
        if (!(d.y < 0.0)) return glm::dvec3(0.0);
        o += ((o.y - level) / -d.y) * d;
        v = *ref::refract(d, {0.0, 1.0, 0.0}, 1.0 / n);
        weight = (1.0 - ref::fresnel_reflectance(-d.y, 1.0, n)) / (n * n);
    }
    double s0 = 0.0, s1 = 0.0;
    lit_interval(scene, o, v, t, s0, s1);
    if (!(s1 > s0)) return glm::dvec3(0.0);
    glm::dvec3 radiance(0.0);
    const glm::dvec3 sigma_t = scene.medium.sigma_t();
    for (int c = 0; c < 3; ++c) {
        auto from_start = [&](double length) {
            return ref::water_path_radiance(
                {scene.medium.sigma_s[c], sigma_t[c], scene.medium.g, level - o.y, length, v, t, e_perp0[c], 0.0});
        };
        radiance[c] = weight * (from_start(s1) - from_start(s0));
    }
    return radiance;
}

inline glm::dvec3 pixel_ray(const Scene& scene, uint32_t width, uint32_t height, int x, int y) {
    return ref::camera_ray(scene.camera, width, height, x + 0.5, y + 0.5).direction;
}

// The godray blur (passes/godrays/godrays_blur.hpp) of the expected values around pixel (x, y): binomial
// weights 1 4 6 4 1 along both axes, for pixels far from the image's border whose neighbours all
// see the same surface (every tap kept).
inline glm::dvec3 expected_blurred(const Scene& scene, uint32_t width, uint32_t height, int x, int y) {
    constexpr double kWeights[5] = {1, 4, 6, 4, 1};
    glm::dvec3 sum(0.0);
    for (int j = -2; j <= 2; ++j) {
        for (int i = -2; i <= 2; ++i) {
            sum += kWeights[i + 2] * kWeights[j + 2] *
                   expected_in_scatter(scene, pixel_ray(scene, width, height, x + i, y + j));
        }
    }
    return sum / 256.0;
}

}  // namespace vkw::test
