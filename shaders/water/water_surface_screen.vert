#version 450
#extension GL_GOOGLE_include_directive : require
// The water surface drawn from a grid that follows the screen (a projected grid,
// docs/techniques/water_surface.md): screen_cells_x x screen_cells_y cells spread evenly over the viewport,
// widened by screen_margin past each edge, so that a cell is about as many pixels wide wherever
// it is seen. Vertex (i, j) stands for the grid parameter where its camera ray meets the mean
// level (or, for a ray that never does, the point on the water's far edge in the ray's
// horizontal direction); it is drawn at the surface point of that parameter, with the analytic
// normal there (for infinite water beyond its far field, at that point of the flat level). For
// infinite water the square is one that holds all the camera can see, so rays that miss the level
// end at the horizon. The grid stops a cell's diagonal past the water's square, and the fragment
// shader leaves out the pixels whose surface point lies outside it: the square's edge is then
// exact per pixel, not the chords of cells clamped onto it. As for the uniform mesh
// (water_surface.vert), one triangle strip per row of cells, an instance each, and the
// fragment shader finds the exact surface from the interpolated parameter.
#include "common/camera_ray.glsl"
#include "water/surface_refinement.glsl"

layout(location = 0) out vec3 out_position;
layout(location = 1) out vec3 out_normal;
layout(location = 2) out vec2 out_parameter;
layout(location = 3) out float out_mesh_sag;

// The parameter vertex ij stands for, before the grid is cut at the square.
vec2 screen_grid_parameter(ivec2 ij) {
    const vec2 cells = vec2(params.screen_cells_x, params.screen_cells_y);
    const vec2 ndc = (2.0 * vec2(ij) / cells - 1.0) * (1.0 + params.screen_margin);
    const vec3 eye = frame.camera_position.xyz;
    const vec3 d = camera_ray_through_ndc(ndc);
    // Beyond the square's farthest corner every point clamps onto its edge anyway; stopping
    // there keeps the rays near the horizon (and the rays that miss the level) finite.
    const vec2 farthest = abs(eye.xz) + params.half_extent;
    const float t_far = length(farthest) / max(length(d.xz), 1e-6);
    const float t_level = (params.level - eye.y) / d.y;
    const float t = t_level > 0.0 && t_level < t_far ? t_level : t_far;
    return eye.xz + t * d.xz;
}

void main() {
    // Row j of cells is instance j, one triangle strip zig-zagging between vertex rows j and j + 1.
    const ivec2 ij = ivec2(gl_VertexIndex / 2, gl_InstanceIndex + (gl_VertexIndex & 1));
    const vec2 unclamped = screen_grid_parameter(ij);
    // The sag of the four cells around this vertex, the largest: every vertex of a cell then
    // carries at least that cell's sag, and so does every point the rasteriser interpolates. The
    // mesh lies in the slab |y - level| <= amplitude with the surface, which bounds it too.
    float diagonal_squared = 0.0;
    for (int corner = 0; corner < 4; ++corner) {
        const ivec2 across = ij + ivec2((corner & 1) != 0 ? 1 : -1, (corner & 2) != 0 ? 1 : -1);
        const vec2 offset = screen_grid_parameter(across) - unclamped;
        diagonal_squared = max(diagonal_squared, dot(offset, offset));
    }
    // A cell's diagonal past the square: the cells that hold its edge reach beyond it.
    const vec2 reach = vec2(params.half_extent + sqrt(diagonal_squared));
    const vec2 parameter = clamp(unclamped, -reach, reach);
    vec3 dP_du, dP_dv;
    water_surface_at(parameter, out_position, dP_du, dP_dv);
    out_normal = water_normal(dP_du, dP_dv);
    if (WATER_INFINITE && distance(parameter, frame.camera_position.xz) > params.far_field) {
        // Infinite water's far field is its mean level (water_in_far_field).
        out_position = vec3(parameter.x, params.level, parameter.y);
        out_normal = vec3(0.0, 1.0, 0.0);
    }
    out_parameter = parameter;
    out_mesh_sag = min(params.sag_per_diagonal_squared * diagonal_squared, 2.0 * params.amplitude);
    gl_Position = frame.view_proj * vec4(out_position, 1.0);
}
