// The reference renderer's floor caustics under wavy water (tools/reference/
// floor_caustics.hpp): the flux reaching the floor equals PHYSICS.md section 4's
// integral computed independently here (midpoint quadrature over the analytic surface,
// not the beams' own sum), and a flat surface's beams give the closed-form irradiance.
#include "engine/scene/scene_loader.hpp"
#include "engine/water/surface.hpp"
#include "tools/reference/floor_caustics.hpp"
#include "tools/reference/optics.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <string>

namespace vkw::ref {
namespace {

constexpr double kIor = 1.333;

// One sine along x (A sin(kx)) over water 2 m wide, floor 1 m down and wide enough to
// catch every beam, clear water with a little absorption.
Scene sine_scene(double slope, double sun_elevation_deg) {
    const double wavelength = 0.5, amplitude = slope * wavelength / (2.0 * 3.14159265358979323846);
    return parse_scene(R"({
      "camera": {"position": [0, 2, 3], "target": [0, 0, 0]},
      "sun": {"elevation_deg": )" + std::to_string(sun_elevation_deg) + R"(, "azimuth_deg": 90, "irradiance": [2, 2, 2]},
      "sky": {"radiance": [0, 0, 0]},
      "floor": {"height": -1, "half_extent": 4},
      "water": {"level": 0, "half_extent": 1, "ior": 1.333,
                "waves": {"model": "sum", "components": [{"amplitude": )" + std::to_string(amplitude) +
                       R"(, "wavelength": 0.5, "direction_deg": 0}]}},
      "medium": {"sigma_a": [0.1, 0.2, 0.4], "sigma_s": [0, 0, 0], "g": 0}
    })", "sine.json");
}

// PHYSICS.md section 4: Phi = E_s * integral of max(0, cos(theta_s) - u_h . grad h) T exp(-sigma_t l) dA_h,
// by the midpoint rule on a grid much finer than the beams' (independent of their triangles).
glm::dvec3 section4_flux(const Scene& scene, const WaterSurface& surface, int steps) {
    const glm::dvec3 s = scene.sun.direction, toward_sun = -s;
    const glm::dvec2 u_h{toward_sun.x, toward_sun.z};
    const double extent = scene.water->half_extent, cell = 2.0 * extent / steps;
    glm::dvec3 flux(0.0);
    for (int j = 0; j < steps; ++j) {
        for (int i = 0; i < steps; ++i) {
            const double x = -extent + (i + 0.5) * cell, z = -extent + (j + 0.5) * cell;
            const SurfacePoint p = surface.at_parameter(x, z);
            const glm::dvec2 gradient{-p.normal.x / p.normal.y, -p.normal.z / p.normal.y};
            const double projected = std::max(0.0, toward_sun.y - glm::dot(u_h, gradient));
            const double cos_i = -glm::dot(s, p.normal);
            if (projected <= 0.0 || cos_i <= 0.0) continue;
            const glm::dvec3 t = *refract(s, p.normal, 1.0 / kIor);
            const double path = (p.position.y - scene.floor.height) / -t.y;
            const double transmittance = 1.0 - fresnel_reflectance(cos_i, 1.0, kIor);
            const glm::dvec3 sigma_t = scene.medium.sigma_t();
            flux += scene.sun.irradiance * (projected * transmittance * cell * cell) *
                    glm::dvec3(std::exp(-sigma_t.x * path), std::exp(-sigma_t.y * path), std::exp(-sigma_t.z * path));
        }
    }
    return flux;
}

TEST(reference_floor_caustics, FluxOnTheFloorEqualsTheSection4Integral) {
    for (double slope : {0.1, 0.3}) {
        for (double sun : {90.0, 30.0}) {  // sun 30 degrees above the horizon: 60 from the zenith
            SCOPED_TRACE("slope " + std::to_string(slope) + ", sun elevation " + std::to_string(sun));
            const Scene scene = sine_scene(slope, sun);
            const auto surface = make_surface(scene.water->waves, 0.0, 0.0);
            const FloorCausticMap map(scene, *surface, 512, 512);
            const glm::dvec3 expected = section4_flux(scene, *surface, 2000);
            for (int c = 0; c < 3; ++c) {
                // PHYSICS.md: within 0.5%. The beams are flat triangles with their chord's
                // normal (an O(h^2) error, h = 1/128 of the wavelength here) and the midpoint rule
                // errs by O(h^2) too; both are far inside it.
                EXPECT_NEAR(map.total_flux()[c], expected[c], 0.005 * expected[c]) << "channel " << c;
            }
        }
    }
}

TEST(reference_floor_caustics, FlatSurfaceBeamsGiveTheClosedFormIrradiance) {
    const Scene scene = sine_scene(0.0, 60.0);
    const auto surface = make_surface(scene.water->waves, 0.0, 0.0);
    const FloorCausticMap map(scene, *surface, 256, 128);
    const double cos_s = std::sin(60.0 * 3.14159265358979323846 / 180.0);
    const double sin_t = std::sqrt(1 - cos_s * cos_s) / kIor, cos_t = std::sqrt(1 - sin_t * sin_t);
    const double transmittance = 1.0 - fresnel_reflectance(cos_s, 1.0, kIor);
    for (double x : {-0.5, 0.0, 0.3}) {
        for (int c = 0; c < 3; ++c) {
            const double expected =
                2.0 * cos_s * transmittance * std::exp(-scene.medium.sigma_t()[c] * 1.0 / cos_t);
            // Congruent footprints tile the floor exactly: the polygon clipping's rounding alone.
            EXPECT_NEAR(map.irradiance(x, 0.1)[c], expected, 1e-9 * expected) << "x " << x << " channel " << c;
        }
    }
}

}  // namespace
}  // namespace vkw::ref
