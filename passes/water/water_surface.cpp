// add_water_surface_pass: checks the inputs and adds the passes of the wave model
// (water_surface.hpp).
#include "passes/water/water_surface.hpp"

#include "engine/core/errors.hpp"
#include "engine/water/fft_ocean.hpp"
#include "engine/water/validate_waves.hpp"
#include "passes/water/water_surface_ocean.hpp"
#include "passes/water/water_surface_spectrum.hpp"
#include "passes/water/water_surface_sum.hpp"

#include <cmath>
#include <string>

namespace vkw::passes {

namespace {

constexpr uint32_t kMaxGridResolution = 16384;  // as engine/water/water_volume.cpp

void check_grid(const WaterSurfaceInputs& inputs) {
    if (!std::isfinite(inputs.level) || !std::isfinite(inputs.time) || !std::isfinite(inputs.half_extent) ||
        !(inputs.half_extent > 0.0) || inputs.grid_resolution == 0 || inputs.grid_resolution > kMaxGridResolution) {
        throw InternalError("add_water_surface_pass: level = " + std::to_string(inputs.level) + ", time = " +
                            std::to_string(inputs.time) + ", half_extent = " + std::to_string(inputs.half_extent) +
                            ", grid_resolution = " + std::to_string(inputs.grid_resolution) +
                            ": accepted finite level and time, half_extent > 0, 1 <= grid_resolution <= " +
                            std::to_string(kMaxGridResolution));
    }
}

void check_ocean(const WaterSurfaceInputs& inputs) {
    if (inputs.ocean == nullptr) {
        throw InternalError("add_water_surface_pass: the FFT ocean needs its OceanSpectrumBuffer (inputs.ocean)");
    }
    const FftOceanSpectrum& spectrum = inputs.ocean->spectrum();
    if (spectrum.n != inputs.waves.ocean.resolution || spectrum.patch_size != inputs.waves.ocean.patch_size) {
        throw InternalError("add_water_surface_pass: the OceanSpectrumBuffer holds a " + std::to_string(spectrum.n) +
                            "^2 spectrum of patch " + std::to_string(spectrum.patch_size) + " m, the waves ask for " +
                            std::to_string(inputs.waves.ocean.resolution) + "^2 and " +
                            std::to_string(inputs.waves.ocean.patch_size) + " m: remake it when the waves change");
    }
}

// The model's passes, and the uniform mesh where mesh_resolution differs from the grid's.
WaterSurfaceBuffers add_model_passes(fg::FrameGraph& graph, const WaterSurfaceInputs& inputs,
                                     uint32_t mesh_resolution) {
    check_grid(inputs);
    WaterSurfaceInputs mesh = inputs;
    mesh.grid_resolution = mesh_resolution;
    check_grid(mesh);
    validate_waves(inputs.waves);
    switch (inputs.waves.model) {
        case WaveModel::Flat: return add_wave_sum_passes(graph, inputs, {}, mesh_resolution);
        case WaveModel::Sum:
            if (inputs.waves.components.size() > kMaxGpuWaves) {
                throw UserError("water.waves.components has " + std::to_string(inputs.waves.components.size()) +
                                " waves: accepted 0 to " + std::to_string(kMaxGpuWaves) +
                                " (each vertex of the GPU surface sums them all)");
            }
            return add_wave_sum_passes(graph, inputs, inputs.waves.components, mesh_resolution);
        case WaveModel::FftOcean: check_ocean(inputs); return add_ocean_passes(graph, inputs, mesh_resolution);
    }
    throw InternalError("add_water_surface_pass: unknown wave model");
}

}  // namespace

VkDeviceSize water_surface_bytes(uint32_t grid_resolution) {
    const VkDeviceSize row = VkDeviceSize{grid_resolution} + 1;
    return row * row * kWaterVertexBytes;
}

WaterSurfaceBuffers add_water_surface_passes(fg::FrameGraph& graph, const WaterSurfaceInputs& inputs,
                                             uint32_t mesh_resolution, const ScreenMesh& screen) {
    WaterSurfaceBuffers out =
        add_model_passes(graph, inputs, screen.cell_pixels > 0 ? inputs.grid_resolution : mesh_resolution);
    out.screen = screen;
    return out;
}

fg::BufferHandle add_water_surface_pass(fg::FrameGraph& graph, const WaterSurfaceInputs& inputs) {
    return add_water_surface_passes(graph, inputs, inputs.grid_resolution).grid;
}

}  // namespace vkw::passes
