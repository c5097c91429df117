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

#include <optional>
#include <string>
#include <vector>

namespace vkw::passes {

// Mirrors shaders/water/water_surface_params.glsl: the shading's parameters (filled in by the
// shading pass), then the mesh's and the surface's (water_surface_push).
struct WaterSurfacePush {
    uint32_t mesh_resolution = 0;
    uint32_t reflection_steps = 0, refraction_steps = 0;
    float scene_size = 0.0f;
    float shallow_blend = 0.0f;
    float fresnel_power = 0.0f;
    float blend_k = 0.0f;
    uint32_t refine_steps = 0;
    float water_colour[4] = {};  // a vec4 at offset 32
    float level = 0.0f, half_extent = 0.0f;
    uint32_t wave_count = 0, ocean_n = 0;
    float nodes_per_metre = 0.0f;
    float mesh_sag = 0.0f;
    float bottom_y = 0.0f, amplitude = 0.0f;  // the camera-medium pass's
};
static_assert(sizeof(WaterSurfacePush) == 80);

// The mesh's and the surface's part, with `refine_steps` Newton steps per pixel.
WaterSurfacePush water_surface_push(const WaterSurfaceBuffers& surface, uint32_t refine_steps);

// The draw's reads: the mesh at binding 2 (vertex stage), the wave table at 11 and the ocean's
// fields at 12 (fragment stage; for the wave sum the mesh stands in at 12, never read).
struct WaterSurfaceReads {
    fg::BufferHandle mesh, waves;
    std::optional<fg::BufferHandle> ocean_fields;
    uint32_t mesh_resolution = 0;
    // The fragment stage's constant_id 0, WATER_SURFACE_MODEL of water/surface_refinement.glsl:
    // 0 flat water (its mesh is the surface), 1 the wave sum, 2 the FFT ocean.
    uint32_t surface_model = 0;

    void declare(fg::PassBuilder& builder, const WaterSurfaceBuffers& surface);
    // The fragment stage's bindings alone (11 and 12), for passes that evaluate the surface
    // without drawing the mesh.
    void add_fragment_bindings(const fg::PassContext& context, std::vector<fg::DescriptorBinding>& bindings) const;
    // The mesh's topology, for the pipelines that draw it: one strip per row of cells.
    static constexpr VkPrimitiveTopology kTopology = VK_PRIMITIVE_TOPOLOGY_TRIANGLE_STRIP;
    // Sets the fragment stage's constant 0 (the caller may append more) and returns `key` with
    // the model's name appended (one pipeline per model).
    std::string specialise(GraphicsPipelineDesc& desc, const std::string& key) const;
    void add_bindings(const fg::PassContext& context, std::vector<fg::DescriptorBinding>& bindings) const;
    // Draws the mesh's 2 M^2 triangles (one strip per row of cells, an instance each), the
    // pipeline (specialised) and its bindings already bound.
    void draw(fg::PassContext& context) const;
};

}  // namespace vkw::passes
