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
#include <vector>

namespace vkw::passes {

// Mirrors shaders/water/water_surface_params.glsl: the shading's parameters (filled in by the
// shading pass), then the mesh's and the surface's (water_surface_push).
struct WaterSurfacePush {
    uint32_t mesh_resolution = 0;
    uint32_t reflection_method = 0, refraction_method = 0;  // SCENE_LOOKUP_*: 0 off, 1 projective, 2 screen-space
    uint32_t reflection_steps = 0, refraction_steps = 0;
    float scene_size = 0.0f;
    float shallow_blend = 0.0f;
    uint32_t fresnel = 0;  // 0 exact, 1 Schlick, 2 Optical Phenomena c. 2008's power term
    float fresnel_power = 0.0f;
    uint32_t depth_blend = 0;  // 1: Optical Phenomena c. 2008's depth colour
    float blend_k = 0.0f;
    float unused0 = 0.0f;  // water_colour is a vec4 at offset 48
    float water_colour[4] = {};
    float level = 0.0f, half_extent = 0.0f;
    uint32_t surface_model = 0;  // 0 the wave sum, 1 the FFT ocean
    uint32_t wave_count = 0, ocean_n = 0;
    float nodes_per_metre = 0.0f;
    uint32_t refine_steps = 0;
    float mesh_sag = 0.0f;
};
static_assert(sizeof(WaterSurfacePush) == 96);

// The mesh's and the surface's part, with `refine_steps` Newton steps per pixel (none for flat
// water).
WaterSurfacePush water_surface_push(const WaterSurfaceBuffers& surface, uint32_t refine_steps);

// The draw's reads: the mesh at binding 2 (vertex stage), the wave table at 11 and the ocean's
// fields at 12 (fragment stage; for the wave sum the mesh stands in at 12, never read).
struct WaterSurfaceReads {
    fg::BufferHandle mesh, waves;
    std::optional<fg::BufferHandle> ocean_fields;
    uint32_t mesh_resolution = 0;

    void declare(fg::PassBuilder& builder, const WaterSurfaceBuffers& surface);
    void add_layout(std::vector<VkDescriptorSetLayoutBinding>& layout) const;
    void add_bindings(const fg::PassContext& context, std::vector<fg::DescriptorBinding>& bindings) const;
    // Draws the mesh's 2 M^2 triangles, the pipeline and its bindings already bound.
    void draw(fg::PassContext& context) const;
};

}  // namespace vkw::passes
