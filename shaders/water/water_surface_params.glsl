// The push constants of the water surface's draw (water_surface.vert or
// water_surface_screen.vert, and .frag) and of the camera-medium pass (camera_medium_mask.frag);
// their C++ type, WaterSurfacePush in passes/water/water_surface_draw.hpp, is generated from
// water_surface.frag. The choices that change which code runs (the wave model, the Fresnel form,
// the lookups, the screen's grid) are specialization constants instead.
#ifndef VKWATER_WATER_SURFACE_PARAMS_GLSL
#define VKWATER_WATER_SURFACE_PARAMS_GLSL

layout(push_constant) uniform Params {
    uint mesh_resolution;   // M: the drawn mesh's cells per side
    uint reflection_steps, refraction_steps;
    float scene_size;       // m: how far a screen-space march looks when no floor bounds it
    float shallow_blend;    // m: see water_surface.frag; 0 off
    float fresnel_power;    // q of Optical Phenomena c. 2008's power term
    float blend_k;          // the depth colour's k, 1/m
    uint refine_steps;      // Newton steps per pixel; 0: the mesh as drawn
    vec4 water_colour;      // rgb: the depth colour's C_w (radiance)
    // The surface itself, for the per-pixel refinement (water/surface_refinement.glsl).
    float level;            // mean water level y, m
    float half_extent;      // E: the mesh spans [-E, E]^2
    uint wave_count;        // the sum's waves
    uint ocean_n;           // the ocean's nodes per side
    float nodes_per_metre;  // n / patch_size
    float mesh_sag;         // m: how far the uniform mesh may lie from the surface (a cell's chord)
    float bottom_y;         // the water volume's bottom (the camera-medium pass; infinite water's shading)
    float amplitude;        // a bound on |surface height - level| (the camera-medium pass, the screen mesh)
    // The screen's grid (water/water_surface_screen.vert and, in the fragment stage, the code
    // that constant WATER_SCREEN_GRID compiles in); unused by the uniform mesh.
    uint screen_cells_x, screen_cells_y;  // cells across and down the widened viewport
    float screen_margin;    // NDC: how far the grid reaches past each edge of the viewport
    float sag_per_diagonal_squared;  // 1/m: a cell's sag over its diagonal squared (|d^2 P / du^2| / 8)
    float march_step;       // m: the refinement's march step along a long window (0: no march)
    float slope_bound;      // a bound on the surface's slope over world x, z (0: none known)
    float far_field;        // m: infinite water's far field (WATER_INFINITE); else unused
} params;

#endif
