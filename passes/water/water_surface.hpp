// The water surface on the GPU: one entry point that adds the compute passes of the scene's
// wave model to the frame graph and returns the vertex grid they write. The CPU surfaces of
// engine/water/ (double precision) are the ground truth; the kernels evaluate the same
// formulas in fp32 (tests/water_gpu/ compares them at every vertex).
//
// The grid: (R + 1) x (R + 1) vertices, R = grid_resolution, whose parameters (x0, z0) are
// -E + 2 E i / R for i, j = 0..R, E = half_extent; vertex (i, j) is element j (R + 1) + i of a
// storage buffer of
//   struct { vec4 position; vec4 normal; }  (std430, 32 bytes)
// position = (x0 + Dx, level + h, z0 + Dz, 1): Gerstner waves and a choppy ocean move points
// sideways, so the grid is displaced; normal = (unit normal toward the air, 0).
//
// The models (WaveSettings::model):
//   Flat     the wave-sum kernel with no waves: (x0, level, z0), normal +y.
//   Sum      shaders/water/wave_sum.comp, sines and Gerstner waves with analytic tangents
//            (passes/water/water_surface_sum.cpp); at most kMaxGpuWaves components.
//   FftOcean h0 from the CPU (OceanSpectrumBuffer), its time evolution, an inverse FFT in
//            compute, and the grid sampled bilinearly from the periodic n x n result
//            (passes/water/water_surface_ocean.cpp). Exact at vertices that fall on FFT nodes.
// Everything is a function of (inputs, seed): two runs give bit-identical vertices.
#pragma once

#include "engine/framegraph/frame_graph.hpp"
#include "engine/water/wave_params.hpp"

#include <cstdint>
#include <optional>

namespace vkw::passes {

class OceanSpectrumBuffer;

// Each vertex sums every wave: the cost grows with the count, which the GPU caps.
inline constexpr uint32_t kMaxGpuWaves = 64;
inline constexpr VkDeviceSize kWaterVertexBytes = 32;

struct WaterSurfaceInputs {
    double level = 0.0;              // mean water level y, m
    double half_extent = 10.0;       // E, m: the grid spans [-E, E]^2
    uint32_t grid_resolution = 256;  // R cells per side, 1..16384
    double time = 0.0;               // s
    WaveSettings waves;
    // FftOcean only: the device copy of the CPU's h0 for these waves (its spectrum() is the
    // CPU FftOceanSpectrum). Owned by the caller, alive until the frame has executed.
    const OceanSpectrumBuffer* ocean = nullptr;
};

// The scene's wave model as the water's per-pixel refinement evaluates it
// (shaders/water/surface_refinement.glsl): the sum's wave table or the ocean's fields.
struct WaterSurfaceModel {
    bool ocean = false;
    uint32_t wave_count = 0;       // the sum's waves in the table
    uint32_t ocean_n = 0;          // the ocean's nodes per side
    float nodes_per_metre = 0.0f;  // n / patch_size
    float level = 0.0f, half_extent = 0.0f;
    // 1/m: a bound on a flat cell's distance from the surface over the cell's diagonal squared,
    // |d^2 P / du^2| / 8 (per unit of parameter squared).
    float sag_per_diagonal_squared = 0.0f;
    float mesh_sag = 0.0f;  // m: that bound for a cell of the uniform mesh
    // m: the horizontal run of the per-pixel march that brackets the first crossing where the
    // screen's grid is coarse: an eighth of the shortest wavelength (the ocean: its node spacing).
    float march_step = 0.0f;
    // A bound on the height's slope over world (x, z), for the march's steps; 0: none (the ocean,
    // or waves steep enough to fold).
    float slope_bound = 0.0f;
};

// The water drawn from a grid that follows the screen (shaders/water/water_surface_screen.vert)
// instead of the uniform mesh: cells about `cell_pixels` wide wherever they are seen, reaching
// `margin` (NDC) past each edge of the viewport, so that the waves' displacement cannot pull
// the mesh's edge into view (water_screen_mesh.hpp computes it). cell_pixels = 0: the uniform mesh.
struct ScreenMesh {
    uint32_t cell_pixels = 0;
    float margin = 0.0f;
    float amplitude = 0.0f;  // m: a bound on |surface height - level|
    // Infinite water (only ever drawn from this grid): the square the surface is drawn over (it
    // holds all the camera can see, engine/scene water_drawn_half_extent), the far field's
    // distance (kInfiniteWaterFarField) and the water's bottom, which a ray under the water that
    // meets no receiver runs to.
    bool infinite = false;
    float drawn_half_extent = 0.0f;
    float far_field = 0.0f;
    float bottom_y = 0.0f;
};

// What the surface's passes leave for their readers.
struct WaterSurfaceBuffers {
    fg::BufferHandle grid;  // the (R + 1)^2 vertices: the photons, the godrays and the stencil split
    // The (M + 1)^2 vertices of the mesh the water is drawn with (M = mesh_resolution); the grid
    // itself when M = R or the water is drawn from the screen's grid (`screen`).
    fg::BufferHandle mesh;
    uint32_t mesh_resolution = 0;
    ScreenMesh screen;
    // The sum's wave table (a uniform buffer of kMaxGpuWaves waves), for the ocean an empty one:
    // the refinement's shader declares both models' bindings.
    fg::BufferHandle waves;
    std::optional<fg::BufferHandle> ocean_fields;  // the FFT's fields (water_surface_ocean.hpp)
    WaterSurfaceModel model;
};

// Adds the passes: the grid at R = inputs.grid_resolution, and the drawn mesh at
// `mesh_resolution` cells per side (1..16384) from the same waves or fields; with
// screen.cell_pixels > 0 no mesh (the screen's grid needs none, mesh_resolution is unused).
WaterSurfaceBuffers add_water_surface_passes(fg::FrameGraph& graph, const WaterSurfaceInputs& inputs,
                                             uint32_t mesh_resolution, const ScreenMesh& screen = {});

// Adds the passes and returns the vertex buffer (written by a compute pass; declare the
// reader's use, e.g. read_storage with the vertex stage, on the returned handle).
// Throws vkw::UserError for waves a scene must not contain (validate_waves) or more than
// kMaxGpuWaves components, vkw::InternalError for a non-finite level or time, E <= 0, R
// outside 1..16384, or an FFT ocean without its OceanSpectrumBuffer (or with one made for
// another resolution or patch size).
fg::BufferHandle add_water_surface_pass(fg::FrameGraph& graph, const WaterSurfaceInputs& inputs);

// (R + 1)^2 vertices, the buffer's size in bytes.
VkDeviceSize water_surface_bytes(uint32_t grid_resolution);

}  // namespace vkw::passes
