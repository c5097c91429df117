// The scene lookups' visibility against closed forms: flat water seen straight down through a
// narrow field of view, a plane receiver under the water and one above the camera. Every refracted
// ray meets the lower plane, every reflected ray the upper one, so the visibilities are the
// Fresnel weights at near-normal incidence, the refracted one times the medium's transmittance
// over its path to the lower plane.
#include "tools/vkwater/budget/lookup_visibility.hpp"

#include "engine/scene/scene_loader.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>

namespace vkw::budget {
namespace {

constexpr double kPi = 3.14159265358979323846;

// Water at y = 0 (n = 1.333) over a floor 5 m down; planes at y = -1 and y = 2; the camera 1 m up
// looking straight down with a 10-degree field of view; the medium absorbs 0.5 per metre.
Scene two_planes(bool with_planes) {
    const std::filesystem::path file = std::filesystem::temp_directory_path() / "vkwater_lookup_visibility.json";
    std::ofstream(file) << R"({
  "camera": { "position": [0, 1, 0], "direction": [0, -1, 0.0001], "fov_y_deg": 10, "near": 0.05, "far": 200 },
  "sun": { "elevation_deg": 60, "azimuth_deg": 0, "irradiance": [2, 2, 2] },
  "sky": { "model": "constant", "radiance": [0.4, 0.5, 0.6] },
  "floor": { "height": -5, "half_extent": 100 },
  "water": { "level": 0, "ior": 1.333, "half_extent": 100, "grid_resolution": 64, "waves": { "model": "flat" } },
  "medium": { "sigma_a": [0.5, 0.6, 0.7], "sigma_s": [0, 0, 0] })"
                        << (with_planes ? R"(,
  "receivers": [
    { "type": "plane", "half_size": [100, 100], "translation": [0, -1, 0] },
    { "type": "plane", "half_size": [100, 100], "translation": [0, 2, 0] }
  ])"
                                        : "")
                        << "\n}\n";
    return load_scene(file);
}

// Unpolarised Fresnel reflectance from air into water of index n, at incidence angle `theta`.
double fresnel(double theta, double n) {
    const double sin_t = std::sin(theta) / n, cos_t = std::sqrt(1.0 - sin_t * sin_t), cos_i = std::cos(theta);
    const double rs = (cos_i - n * cos_t) / (cos_i + n * cos_t), rp = (n * cos_i - cos_t) / (n * cos_i + cos_t);
    return 0.5 * (rs * rs + rp * rp);
}

TEST(LookupVisibility, NearNormalIncidenceGivesTheFresnelWeights) {
    const LookupVisibility visibility = lookup_visibility(two_planes(true), 4.0 / 3.0);
    // Bounds over the frame's rays: the widest, along the diagonal of a 4:3 frame with a 10-degree
    // vertical field, is atan(tan(5 deg) * 5 / 3) = 8.30 degrees from the axis. R rises from R(0) =
    // ((n - 1) / (n + 1))^2 to R(8.30 deg) across the frame, and the refracted path to the plane 1 m
    // down from 1 m to 1 / cos_t at that angle (sin_t = sin_i / n), in the least absorbing channel
    // (0.5 /m).
    const double n = 1.333, widest = std::atan(std::tan(5.0 * kPi / 180.0) * 5.0 / 3.0);
    const double sin_t = std::sin(widest) / n, longest = 1.0 / std::sqrt(1.0 - sin_t * sin_t);
    EXPECT_NEAR(fresnel(0.0, n), std::pow((n - 1.0) / (n + 1.0), 2.0), 1e-15);
    EXPECT_GE(visibility.reflection, fresnel(0.0, n));
    EXPECT_LE(visibility.reflection, fresnel(widest, n));
    EXPECT_LE(visibility.refraction, (1.0 - fresnel(0.0, n)) * std::exp(-0.5));
    EXPECT_GE(visibility.refraction, (1.0 - fresnel(widest, n)) * std::exp(-0.5 * longest));
}

TEST(LookupVisibility, NothingToMeetGivesNothing) {
    const LookupVisibility visibility = lookup_visibility(two_planes(false), 4.0 / 3.0);
    EXPECT_EQ(visibility.reflection, 0.0);
    EXPECT_EQ(visibility.refraction, 0.0);
}

}  // namespace
}  // namespace vkw::budget
