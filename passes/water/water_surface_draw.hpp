// What every draw of the water's mesh shares (shaders/water/water_surface.vert for the uniform
// mesh or water_surface_screen.vert for the screen's grid, with water/surface_refinement.glsl
// in the fragment shader): the reads of the mesh, the wave table
// and the ocean's fields, their bindings, and the push constants of
// shaders/water/water_surface_params.glsl. The water's shading pass is one such draw; the
// refinement's tests draw the same mesh with a probe shader.
#pragma once

#include "engine/framegraph/frame_graph.hpp"
#include "engine/framegraph/pass_context.hpp"
#include "engine/vk/pipeline.hpp"
#include "passes/water/water_surface.hpp"

#include <shader_structs/water/water_surface.frag.hpp>

#include <optional>
#include <string>
#include <vector>

namespace vkw::passes {

// The push block of shaders/water/water_surface_params.glsl, generated from the water shader's
// SPIR-V (tools/shader_structs): the shading's parameters (filled in by the shading pass), then the
// mesh's and the surface's (water_surface_push), then the camera-medium pass's.
using WaterSurfacePush = glsl::water_surface_frag::Params;

// The mesh's and the surface's part, with `refine_steps` Newton steps per pixel.
WaterSurfacePush water_surface_push(const WaterSurfaceBuffers& surface, uint32_t refine_steps);

// The draw's reads: the uniform mesh (`Surface`, vertex stage), the wave table (`Waves`) and the
// ocean's fields (`Grids`, fragment stage, and the vertex stage for the screen's grid, which
// evaluates the surface at its vertices). Without an ocean the mesh stands in for the fields,
// never read (for the screen's grid, the photon grid does).
struct WaterSurfaceReads {
    std::optional<fg::BufferHandle> mesh;
    fg::BufferHandle waves;
    std::optional<fg::BufferHandle> ocean_fields;
    uint32_t mesh_resolution = 0;
    ScreenMesh screen;
    // The fragment stage's constant_id 0, WATER_SURFACE_MODEL of water/surface_refinement.glsl:
    // 0 flat water (its mesh is the surface), 1 the wave sum, 2 the FFT ocean.
    uint32_t surface_model = 0;

    void declare(fg::PassBuilder& builder, const WaterSurfaceBuffers& surface);
    // What stands in for the reads the surface model never makes, for PassContext::bind's `extra`.
    std::vector<fg::DescriptorBinding> stand_ins(const fg::PassContext& context) const;
    // The mesh's topology, for the pipelines that draw it: one strip per row of cells.
    static constexpr VkPrimitiveTopology kTopology = VK_PRIMITIVE_TOPOLOGY_TRIANGLE_STRIP;
    // The vertex shader that draws the mesh.
    const char* vertex_shader() const;
    // Sets constants 0 and 1, the model and whether the screen's grid is drawn (the caller may
    // append more), and returns `key` with both appended (one pipeline each).
    std::string specialise(GraphicsPipelineDesc& desc, const std::string& key) const;
    // Pushes `push` with the screen grid's cells for this image, then draws the mesh's triangles
    // (one strip per row of cells, an instance each), the pipeline (specialised) and its bindings
    // already bound.
    void draw(fg::PassContext& context, const Pipeline& pipeline, WaterSurfacePush push) const;
};

}  // namespace vkw::passes
