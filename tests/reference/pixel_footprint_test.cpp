// The reference's measure of its caustic texels against the pixels (tools/reference/
// pixel_footprint.hpp and FloorCausticMap::irradiance_over_double_texels): over flat water the
// footprints follow from Snell's law by hand, and the 2 x 2 block mean of a map is the map of
// half as many texels.
#include "tools/reference/pixel_footprint.hpp"
#include "engine/scene/scene_loader.hpp"
#include "engine/water/surface.hpp"
#include "tests/reference/sine_scene.hpp"
#include "tools/reference/floor_caustics.hpp"
#include "tools/reference/reference_renderer.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

namespace vkw::ref {
namespace {

TEST(reference_pixel_footprint, FlatWaterFootprintsFollowSnellsLawByHand) {
    // A camera 2 m above flat water 3 m deep, looking down at 60 degrees: each pixel centre's
    // floor point computed here by hand (the ray meets y = 0, bends by Snell's law, meets
    // y = -3), and the footprint widths from those points, must equal the reference's.
    const double n = 1.333;
    const uint32_t width = 64, height = 48;
    const Scene scene = parse_scene(R"({
      "camera": {"position": [0, 2, 0], "direction": [0, -1.7320508, -1], "fov_y_deg": 40},
      "sun": {"elevation_deg": 70, "azimuth_deg": 0, "irradiance": [2, 2, 2]},
      "sky": {"radiance": [0, 0, 0]},
      "floor": {"height": -3, "half_extent": 40},
      "water": {"level": 0, "half_extent": 40, "ior": 1.333}
    })",
                                    "flat.json");
    WaterTransport::Quality geometry;
    geometry.caustics = false;
    const PixelFootprints footprints =
        under_water_pixel_footprints(scene, WaterTransport(scene, geometry), width, height);
    ASSERT_EQ(footprints.widths.size(), size_t{width - 1} * (height - 1));  // every pixel but the last row and column

    auto floor_point = [&](uint32_t x, uint32_t y) {
        const Ray ray = camera_ray(scene.camera, width, height, x + 0.5, y + 0.5);
        const glm::dvec3 entry = ray.origin + (-ray.origin.y / ray.direction.y) * ray.direction;
        const glm::dvec2 across = glm::dvec2(ray.direction.x, ray.direction.z) / n;  // tangential part shrinks by n
        const double down = std::sqrt(1.0 - glm::dot(across, across));
        return glm::dvec3(entry.x, 0.0, entry.z) + (3.0 / down) * glm::dvec3(across.x, -down, across.y);
    };
    std::vector<double> expected;
    for (uint32_t y = 0; y + 1 < height; ++y) {
        for (uint32_t x = 0; x + 1 < width; ++x) {
            const glm::dvec3 a = floor_point(x + 1, y) - floor_point(x, y),
                             b = floor_point(x, y + 1) - floor_point(x, y);
            const double area = glm::length(glm::cross(a, b));
            expected.push_back(
                std::min({glm::length(a), glm::length(b), area / std::max(glm::length(a), glm::length(b))}));
        }
    }
    std::sort(expected.begin(), expected.end());
    for (size_t i = 0; i < expected.size(); i += 97) {
        // The reference offsets its rays by 1e-9 m off the surface before going on (a shift of
        // the same size for neighbouring rays: it cancels in the differences far below 1e-9 relative).
        EXPECT_NEAR(footprints.widths[i], expected[i], 1e-9 * expected[i]) << "rank " << i;
    }
    EXPECT_DOUBLE_EQ(footprints.quantile(0.0), footprints.widths.front());
    EXPECT_DOUBLE_EQ(footprints.quantile(1.0), footprints.widths.back());
    EXPECT_DOUBLE_EQ(footprints.fraction_at_least(0.0), 1.0);
    EXPECT_DOUBLE_EQ(footprints.fraction_at_least(2.0 * footprints.widths.back()), 0.0);
}

TEST(reference_pixel_footprint, TheBlockMeanIsTheMapOfHalfTheTexels) {
    // Both maps deposit the same beams by exact polygon overlap, so a coarse texel holds the
    // mean of the four fine texels it covers to the clipping's rounding.
    const Scene scene = sine_scene_with_amplitude(0.01, 60.0);
    const auto surface = make_surface(scene.water->waves, 0.0, 0.0);
    const FloorCausticMap fine(scene, *surface, 128, 256), coarse(scene, *surface, 64, 256);
    double largest = 0.0;
    for (double x = -3.9; x < 3.9; x += 0.0137) {
        for (double z : {-1.0, 0.02, 0.7}) {
            const glm::dvec3 expected = coarse.irradiance(x, z);
            for (int c = 0; c < 3; ++c) {
                EXPECT_NEAR(fine.irradiance_over_double_texels(x, z)[c], expected[c], 1e-9 * (1.0 + expected[c]))
                    << "x " << x << " z " << z;
            }
            largest = std::max(largest, expected[0]);
        }
    }
    EXPECT_GT(largest, 1.0);  // the points were lit
}

}  // namespace
}  // namespace vkw::ref
