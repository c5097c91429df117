// The reference renderer on the FFT ocean (which it once refused): a small
// render of scenes/ocean.json (64 modes over 32 m, coarse caustics) is finite and
// non-negative with the caustic in-scatter on, lights the floor it sees through the water, and
// reports what it approximates.
#include "engine/scene/scene_loader.hpp"
#include "tools/reference/reference_renderer.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>

namespace vkw::ref {
namespace {

TEST(reference_ocean, SmallOceanRendersWithItsErrorBoundsReported) {
    const Scene scene = load_scene(std::filesystem::path(VKWATER_SOURCE_DIR) / "scenes/ocean.json",
                                   {"water.waves.resolution=64", "water.waves.patch_size=32"});
    ReferenceOptions options;
    options.width = 32;
    options.height = 24;
    options.quality.ocean_floor_texels = 128;
    options.quality.ocean_cells_per_period = 128;
    options.quality.caustic_in_scatter = true;
    options.quality.in_scatter_levels = 4;
    options.quality.ocean_in_scatter_texels = 128;
    options.quality.ocean_in_scatter_cells = 128;
    ReferenceReport report;
    const ImageRGBA32F image = render_reference(scene, options, &report);
    for (float v : image.rgba) {
        ASSERT_TRUE(std::isfinite(v));
        ASSERT_GE(v, 0.0f);
    }
    // The lower half of the picture looks into the water: the floor it sees is lit.
    const ExtraLayer& caustic = image.layers.at(0);
    ASSERT_EQ(caustic.name, "caustic");
    EXPECT_GT(caustic.rgb[3 * (20 * 32 + 16) + 2], 0.0f);
    EXPECT_GT(report.caustic_refinement_change, 0.0);
    EXPECT_GT(report.surface_height_error_bound, 0.0);
    EXPECT_GT(report.surface_slope_error_bound, 0.0);
    // Infinite water's far field, the sampled surface and periodic map, the modulated in-scatter's.
    ASSERT_EQ(report.approximations.size(), 3u);
    EXPECT_EQ(report.approximations[0].rfind("infinite water: ", 0), 0u) << report.approximations[0];
}

}  // namespace
}  // namespace vkw::ref
