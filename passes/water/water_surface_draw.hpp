// What every draw of the water's mesh shares (shaders/water/water_surface.vert with
// water/surface_refinement.glsl in its fragment shader): the reads of the mesh, the wave table
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

// The draw's reads: the mesh (`Surface`, vertex stage), the wave table (`Waves`) and the ocean's
// fields (`Grids`, fragment stage; without an ocean the mesh stands in, never read).
struct WaterSurfaceReads {
    fg::BufferHandle mesh, waves;
    std::optional<fg::BufferHandle> ocean_fields;
    uint32_t mesh_resolution = 0;
    // The fragment stage's constant_id 0, WATER_SURFACE_MODEL of water/surface_refinement.glsl:
    // 0 flat water (its mesh is the surface), 1 the wave sum, 2 the FFT ocean.
    uint32_t surface_model = 0;

    void declare(fg::PassBuilder& builder, const WaterSurfaceBuffers& surface);
    // What stands in for the reads the surface model never makes, for PassContext::bind's `extra`.
    std::vector<fg::DescriptorBinding> stand_ins(const fg::PassContext& context) const;
    // The mesh's topology, for the pipelines that draw it: one strip per row of cells.
    static constexpr VkPrimitiveTopology kTopology = VK_PRIMITIVE_TOPOLOGY_TRIANGLE_STRIP;
    // Sets the fragment stage's constant 0 (the caller may append more) and returns `key` with
    // the model's name appended (one pipeline per model).
    std::string specialise(GraphicsPipelineDesc& desc, const std::string& key) const;
    // Draws the mesh's 2 M^2 triangles (one strip per row of cells, an instance each), the
    // pipeline (specialised) and its bindings already bound.
    void draw(fg::PassContext& context) const;
};

}  // namespace vkw::passes
