// What the water-surface grid kernels share on the C++ side (shaders/water/water_vertex.glsl
// on the GLSL side): the head of their push constants, the vertex buffer, the dispatch over
// the (R + 1)^2 vertices in bands of rows that each fit one storage-buffer binding, and the
// compute pass that declares and records all that.
#pragma once

#include "engine/framegraph/frame_graph.hpp"
#include "engine/framegraph/pass_context.hpp"
#include "passes/water/water_surface.hpp"

#include <vulkan/vulkan.h>
#include <shader_structs/common/shared_blocks.comp.hpp>

#include <cstdint>
#include <vector>

namespace vkw::passes {

// struct WaterGrid of shaders/water/water_vertex.glsl, generated once from common/shared_blocks.comp
// (every grid kernel's push block begins with one): level, half_extent, resolution, and the band's
// first_row and band_rows, which dispatch_water_grid sets.
using WaterGridPush = glsl::shared_blocks_comp::WaterGrid;

WaterGridPush water_grid_push(const WaterSurfaceInputs& inputs);

// Declares the vertex buffer in `builder`'s pass as a new buffer written by its shader.
fg::BufferHandle create_water_vertices(fg::PassBuilder& builder, uint32_t grid_resolution);

struct WaterGridBand {
    uint32_t row_vertices;  // R + 1
    uint32_t first_row;
    uint32_t rows;
    VkDeviceSize offset, bytes;  // of the band's vertices in the buffer
};

// The bands: as many rows as one binding may span (max_range, the device's
// maxStorageBufferRange), rounded down to a multiple of the rows that keep each band's offset
// aligned to `alignment` (minStorageBufferOffsetAlignment). One band up to R = 2047 on
// lavapipe (128 MiB).
std::vector<WaterGridBand> water_grid_bands(VkDeviceSize max_range, VkDeviceSize alignment, uint32_t grid_resolution);
// The same for the device that `context` records for.
std::vector<WaterGridBand> water_grid_bands(const fg::PassContext& context, uint32_t grid_resolution);

// Binds and dispatches one band, the push constants already filled in.
void dispatch_water_band(fg::PassContext& context, const Pipeline& pipeline, fg::BufferHandle vertices,
                         const WaterGridBand& band, const void* push, uint32_t push_bytes);

// Records the grid kernel over every band: `pipeline` with the pass's declared input, the band of
// `vertices` as `Vertices`, and `push` (whose first member is `WaterGridPush grid`) with the
// band's rows filled in.
template <class Push>
void dispatch_water_grid(fg::PassContext& context, const Pipeline& pipeline, fg::BufferHandle vertices, Push push) {
    for (const WaterGridBand& band : water_grid_bands(context, push.grid.resolution)) {
        push.grid.first_row = band.first_row;
        push.grid.band_rows = band.rows;
        dispatch_water_band(context, pipeline, vertices, band, &push, sizeof(Push));
    }
}

// A grid kernel's pass: its name, the kernel's shader and pipeline key, and its input: the
// shader's block `input`, a uniform buffer or (uniform_input false) a storage buffer.
struct WaterGridKernel {
    const char* pass;
    const char* shader;
    const char* pipeline;
    const char* input;
    bool uniform_input;
};

// Adds the compute pass that runs `kernel` over the grid: it reads `input`, writes a new vertex
// buffer (create_water_vertices) band by band (dispatch_water_grid) with `push`, and returns that
// buffer.
template <class Push>
fg::BufferHandle add_water_grid_pass(fg::FrameGraph& graph, const WaterGridKernel& kernel, fg::BufferHandle input,
                                     const Push& push) {
    struct Data {
        fg::BufferHandle vertices;
    };
    const auto& data = graph.add_pass<Data>(
        kernel.pass, fg::PassKind::Compute,
        [&](fg::PassBuilder& builder, Data& d) {
            if (kernel.uniform_input) {
                builder.uniform_buffer(kernel.input, input);
            } else {
                builder.read_storage(kernel.input, input);
            }
            d.vertices = create_water_vertices(builder, push.grid.resolution);
        },
        [kernel, push](const Data& d, fg::PassContext& context) {
            const Pipeline& pipeline = context.pipeline(kernel.pipeline, ComputePipelineDesc{kernel.shader});
            dispatch_water_grid(context, pipeline, d.vertices, push);
        });
    return data.vertices;
}

// How far a mesh cell's flat triangles may lie from the surface they interpolate: h^2 / 8 times
// the bound on |d^2 P / du^2| (per unit of parameter squared), h the cell's diagonal. Sets the
// model's bound per diagonal squared (any cell: the screen's grid) and the bound for a cell of the
// uniform mesh of `mesh_resolution` cells over [-E, E]^2.
inline void set_water_mesh_sag(WaterSurfaceModel& model, double half_extent, uint32_t mesh_resolution,
                               double second_derivative_bound) {
    const double cell = 2.0 * half_extent / mesh_resolution;
    model.sag_per_diagonal_squared = static_cast<float>(second_derivative_bound / 8.0);
    model.mesh_sag = static_cast<float>(2.0 * cell * cell / 8.0 * second_derivative_bound);
}

// The grid kernel's pass at R = push.grid.resolution into out.grid and, where mesh_resolution
// differs, its pass `mesh_pass` at that resolution from the same input into out.mesh (else
// out.mesh is the grid).
template <class Push>
void add_water_grid_and_mesh_passes(fg::FrameGraph& graph, const WaterGridKernel& kernel, const char* mesh_pass,
                                    fg::BufferHandle input, Push push, uint32_t mesh_resolution,
                                    WaterSurfaceBuffers& out) {
    out.grid = add_water_grid_pass(graph, kernel, input, push);
    out.mesh = out.grid;
    out.mesh_resolution = mesh_resolution;
    out.model.level = push.grid.level;
    out.model.half_extent = push.grid.half_extent;
    if (mesh_resolution == push.grid.resolution) return;
    WaterGridKernel mesh_kernel = kernel;
    mesh_kernel.pass = mesh_pass;
    push.grid.resolution = mesh_resolution;
    out.mesh = add_water_grid_pass(graph, mesh_kernel, input, push);
}

}  // namespace vkw::passes
