// Reflections below the horizon in the reference (docs/model.md section 1, "Surface events along a
// path"): a ray that a wave's face reflects downward from the air meets the water again and is
// split there; it never takes the sky's `ground` radiance. Tested on one steep sine seen at grazing
// angles, with a ground so bright that any pixel seeing it would stand out by a factor of 30 or more.
#include "engine/scene/scene_loader.hpp"
#include "tools/reference/water_transport.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>

namespace vkw::ref {
namespace {

constexpr double kAmplitude = 0.0318;  // m: slope A k = 0.4 for the 0.5 m wavelength
constexpr double kWavenumber = 2.0 * std::numbers::pi / 0.5;
const glm::dvec3 kEye{6.0, 0.5, 0.0};

// Sun off (no glints: only the sky and the water's own light reach the eye), a gradient sky whose
// ground is green 1000 W m^-2 sr^-1, one sine h = A sin(k x) along x, the camera looking along -x.
Scene steep_sine_under_a_green_ground() {
    return parse_scene(R"({
      "camera": {"position": [6, 0.5, 0], "target": [-10, 0, 0]},
      "sun": {"elevation_deg": 45, "irradiance": [0, 0, 0]},
      "sky": {"model": "gradient", "zenith": [0.12, 0.25, 0.55], "horizon": [0.55, 0.6, 0.7],
              "ground": [0, 1000, 0], "exponent": 0.5},
      "floor": {"height": -2, "albedo": [0.5, 0.5, 0.5], "half_extent": 6},
      "water": {"level": 0, "half_extent": 6, "ior": 1.333,
                "waves": {"model": "sum", "components": [{"amplitude": 0.0318, "wavelength": 0.5,
                                                         "direction_deg": 0}]}}
    })",
                       "steep_sine.json");
}

double height(double x) { return kAmplitude * std::sin(kWavenumber * x); }
double height_slope(double x) { return kAmplitude * kWavenumber * std::cos(kWavenumber * x); }

// Where the ray from the eye first crosses h(x) (it stays in z = 0): marched in steps far below a
// wavelength, then bisected. The test's own geometry, independent of the reference's.
double first_crossing(const glm::dvec3& d) {
    auto above = [&](double t) { return kEye.y + t * d.y - height(kEye.x + t * d.x) > 0.0; };
    double t = 0.0;
    while (above(t + 1e-3)) t += 1e-3;
    double lo = t, hi = t + 1e-3;
    for (int i = 0; i < 60; ++i) (above(0.5 * (lo + hi)) ? lo : hi) = 0.5 * (lo + hi);
    return hi;
}

TEST(reference_below_horizon, ReflectionsPointingDownSeeTheWaterNotTheGround) {
    const Scene scene = steep_sine_under_a_green_ground();
    const WaterTransport transport(scene);
    // The sky's largest green, without the sun (off): the horizon's 0.6. A pixel that saw the ground
    // through a reflectance of at least 0.02 would read 20 or more.
    const double bound = 2.0 * 0.6;
    int downward = 0, rays = 0;
    for (int i = 0; i < 400; ++i) {
        // View rays from 5 to 40 degrees below the horizon (they meet the water within 5.7 m), all
        // in the plane z = 0.
        const double e = (5.0 + 35.0 * i / 399.0) * std::numbers::pi / 180.0;
        const glm::dvec3 d{-std::cos(e), -std::sin(e), 0.0};
        const double x = kEye.x + first_crossing(d) * d.x;
        const glm::dvec3 normal = glm::normalize(glm::dvec3(-height_slope(x), 1.0, 0.0));
        if (glm::reflect(d, normal).y < 0.0) ++downward;
        ++rays;
        const PixelRadiance pixel = transport.trace_camera_ray({kEye, d});
        EXPECT_LE(pixel.radiance.g, bound) << "view " << e * 180.0 / std::numbers::pi << " deg below the horizon";
    }
    // The test means something only if some first reflections point down (each would have read the
    // ground before). A face turns a ray e below the horizon down where it tilts away from the eye
    // by more than e / 2 and less than e (steeper, it is hidden): a slope of 0.4 (21.8 degrees)
    // allows it up to e = 43.6 degrees, on a small part of each wavelength.
    EXPECT_GE(downward, 10) << downward << " of " << rays;
}

}  // namespace
}  // namespace vkw::ref
