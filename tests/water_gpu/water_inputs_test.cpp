// What add_water_surface_pass refuses, and the banding of large grids (no device needed:
// the checks run while the graph is declared, the banding is a pure function).
#include "engine/core/errors.hpp"
#include "passes/water/water_surface.hpp"
#include "passes/water/water_surface_grid.hpp"

#include <gtest/gtest.h>

#include <string>

namespace vkw::test {
namespace {

passes::WaterSurfaceInputs sum_of(size_t count) {
    passes::WaterSurfaceInputs inputs;
    inputs.grid_resolution = 8;
    inputs.waves.model = WaveModel::Sum;
    inputs.waves.components.assign(count, WaveComponent{0.01, 2.0, 0.0, 0.0, 0.0, -1.0});
    return inputs;
}

TEST(water_gpu_inputs, SixtyFourWavesAreAcceptedAndSixtyFiveRefusedNamingTheField) {
    fg::FrameGraph graph;
    EXPECT_TRUE(passes::add_water_surface_pass(graph, sum_of(64)).valid());
    try {
        passes::add_water_surface_pass(graph, sum_of(65));
        FAIL() << "65 waves accepted";
    } catch (const UserError& e) {
        EXPECT_NE(std::string(e.what()).find("water.waves.components has 65 waves: accepted 0 to 64"),
                  std::string::npos)
            << e.what();
    }
}

TEST(water_gpu_inputs, BadWavesAreRefusedAsTheCpuSurfaceRefusesThem) {
    fg::FrameGraph graph;
    passes::WaterSurfaceInputs inputs = sum_of(2);
    inputs.waves.components[1].wavelength = -1.0;
    EXPECT_THROW(passes::add_water_surface_pass(graph, inputs), UserError);
}

TEST(water_gpu_inputs, OceanWithoutItsSpectrumBufferIsAnInternalError) {
    fg::FrameGraph graph;
    passes::WaterSurfaceInputs inputs;
    inputs.waves.model = WaveModel::FftOcean;
    EXPECT_THROW(passes::add_water_surface_pass(graph, inputs), InternalError);
}

TEST(water_gpu_inputs, DegenerateGridIsAnInternalError) {
    fg::FrameGraph graph;
    passes::WaterSurfaceInputs inputs = sum_of(1);
    inputs.grid_resolution = 0;
    EXPECT_THROW(passes::add_water_surface_pass(graph, inputs), InternalError);
    inputs.grid_resolution = 8;
    inputs.half_extent = 0.0;
    EXPECT_THROW(passes::add_water_surface_pass(graph, inputs), InternalError);
}

TEST(water_gpu_inputs, BandsCoverEveryRowOnceWithAlignedOffsetsWithinTheRange) {
    // R = 100: rows of 101 * 32 = 3232 bytes; a 64 KiB range holds 20 rows, and 256-byte
    // alignment needs a multiple of 8 rows (3232 = 2^5 * 101): bands of 16 rows.
    const auto bands = passes::water_grid_bands(65536, 256, 100);
    uint32_t next = 0;
    for (const passes::WaterGridBand& band : bands) {
        EXPECT_EQ(band.first_row, next);
        EXPECT_EQ(band.row_vertices, 101u);
        EXPECT_EQ(band.offset % 256, 0u);
        EXPECT_LE(band.bytes, 65536u);
        EXPECT_EQ(band.offset, VkDeviceSize{band.first_row} * 3232);
        EXPECT_EQ(band.bytes, VkDeviceSize{band.rows} * 3232);
        next += band.rows;
    }
    EXPECT_EQ(next, 101u);
    EXPECT_EQ(bands.size(), 7u);  // 6 bands of 16 rows and one of 5
    EXPECT_EQ(passes::water_grid_bands(VkDeviceSize{1} << 27, 64, 256).size(), 1u);
}

}  // namespace
}  // namespace vkw::test
