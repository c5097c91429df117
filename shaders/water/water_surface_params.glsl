// The push constants of the water surface's draw (water_surface.vert and .frag), mirrored by
// WaterPush in passes/water/water_shading.cpp.
#ifndef VKWATER_WATER_SURFACE_PARAMS_GLSL
#define VKWATER_WATER_SURFACE_PARAMS_GLSL

layout(push_constant) uniform Params {
    uint mesh_resolution;                       // M: the drawn mesh's cells per side
    uint reflection_method, refraction_method;  // SCENE_LOOKUP_*
    uint reflection_steps, refraction_steps;
    float scene_size;      // m: how far a screen-space march looks when no floor bounds it
    float shallow_blend;   // m: see water_surface.frag; 0 off
    uint fresnel_model;    // SURFACE_FRESNEL_* (effects.water.fresnel)
    float fresnel_power;   // q of Optical Phenomena c. 2008's power term
    uint depth_blend;      // 1: Optical Phenomena c. 2008's depth colour along refracted rays
    float blend_k;         // its k, 1/m
    float unused0;
    vec4 water_colour;     // rgb: its C_w (radiance)
    // The surface itself, for the per-pixel refinement (water/surface_refinement.glsl).
    float level;           // mean water level y, m
    float half_extent;     // E: the mesh spans [-E, E]^2
    uint surface_model;    // WATER_SURFACE_SUM or WATER_SURFACE_OCEAN
    uint wave_count;       // the sum's waves
    uint ocean_n;          // the ocean's nodes per side
    float nodes_per_metre; // n / patch_size
    uint refine_steps;     // Newton steps per pixel; 0: the mesh as drawn
    float mesh_sag;        // m: how far the mesh may lie from the surface (a cell's chord)
} params;

#endif
