// The water surface recovered per pixel from the mesh it is drawn with: the first crossing of
// the view ray with the displaced surface P(x) of the scene's wave model, found by Newton's
// method from the rasterised mesh point (docs/water_surface.md). The mesh
// then only has to be fine enough for Newton to start near the right crossing; the shading sees
// the exact surface and its analytic normal wherever the iteration converges.
//
// Needs the push constants of water/water_surface_params.glsl, the wave table at binding 11
// and the ocean's fields at binding 12 (only the scene's model is read).
#ifndef VKWATER_SURFACE_REFINEMENT_GLSL
#define VKWATER_SURFACE_REFINEMENT_GLSL

#define WATER_WAVES_BINDING 11
#define OCEAN_FIELDS_BINDING 12
#include "water/ocean_point.glsl"
#include "water/water_surface_params.glsl"
#include "water/water_vertex.glsl"
#include "water/wave_sum_point.glsl"

// The scene's model, a specialization constant (passes/water/water_surface_draw.hpp): the other
// models' code is compiled out of the pipeline.
const uint WATER_SURFACE_FLAT = 0u;  // the mesh is the surface: nothing to refine
const uint WATER_SURFACE_SUM = 1u;   // sines and Gerstner waves
const uint WATER_SURFACE_OCEAN = 2u;
layout(constant_id = 0) const uint WATER_SURFACE_MODEL = WATER_SURFACE_SUM;

// A converged crossing misses the surface by at most this times (1 + t) metres: about ten fp32
// ulps of the positions involved (P and eye + t d are sums of terms of magnitude t and |eye|).
const float REFINEMENT_RELATIVE_TOLERANCE = 1e-5;

void water_surface_at(vec2 x, out vec3 position, out vec3 dP_du, out vec3 dP_dv) {
    if (WATER_SURFACE_MODEL == WATER_SURFACE_OCEAN) {
        ocean_point(x, params.level, params.ocean_n, params.nodes_per_metre, position, dP_du, dP_dv);
    } else {
        wave_sum_point(x, params.level, params.wave_count, position, dP_du, dP_dv);
    }
}

// Solves eye + t d = P(x) for the ray parameter t and the grid parameter x, Newton's method on
// all three unknowns at once (the Jacobian's columns d, -dP/dx0, -dP/dz0), which needs no
// inversion of the horizontal displacement of its own: heightfields, Gerstner waves and the
// choppy ocean alike. t and x start at the mesh point's and end at the crossing's. False, and
// nothing written, where the iteration does not meet the surface within the tolerance, meets
// it outside [t_min, t_max] or outside the water's square, or the ray runs parallel to the
// surface: the caller keeps the mesh point there.
bool refine_water_hit(vec3 eye, vec3 d, float t_min, float t_max, inout float t, inout vec2 x, out vec3 position,
                      out vec3 normal) {
    vec3 p, dP_du, dP_dv;
    water_surface_at(x, p, dP_du, dP_dv);
    for (uint i = 0u; i < params.refine_steps; ++i) {
        const vec3 miss = eye + t * d - p;
        if (length(miss) <= REFINEMENT_RELATIVE_TOLERANCE * (1.0 + t)) break;  // converged: no step left to take
        const mat3 jacobian = mat3(d, -dP_du, -dP_dv);
        if (!(abs(determinant(jacobian)) > 1e-12)) return false;
        const vec3 step = inverse(jacobian) * miss;
        t -= step.x;
        x -= step.yz;
        water_surface_at(x, p, dP_du, dP_dv);
    }
    const bool inside = all(lessThanEqual(abs(x), vec2(params.half_extent)));
    if (!(t >= t_min && t <= t_max) || !inside ||
        !(distance(eye + t * d, p) <= REFINEMENT_RELATIVE_TOLERANCE * (1.0 + t))) {
        return false;
    }
    position = p;
    normal = water_normal(dP_du, dP_dv);
    return true;
}

// The surface point a pixel of the drawn mesh shows: the refined crossing of the pixel's view
// ray d (common/camera_ray.glsl: from the eye through the pixel's centre) with the surface, or,
// where refine_water_hit fails, the mesh's point moved onto that ray and the mesh's normal.
// Returns whether it refined. The ray is the pixel's own rather than the direction to the
// rasterised mesh point: a varying interpolated over a large cell carries an error relative
// to the cell's coordinates (tens of metres), which turns the direction by about 1e-6 rad on
// some GPUs, and the shading amplifies that near the critical angle (Snell's window's edge).
// Flat water's crossing is the ray's with the plane y = level, exactly.
bool water_surface_of_pixel(vec3 eye, vec3 d, vec3 mesh_position, vec3 mesh_normal, vec2 mesh_parameter,
                            out vec3 position, out vec3 normal) {
    normal = normalize(mesh_normal);
    float t = dot(mesh_position - eye, d);
    if (WATER_SURFACE_MODEL == WATER_SURFACE_FLAT) {
        const float to_plane = (params.level - eye.y) / d.y;
        if (to_plane > 0.0 && !isinf(to_plane)) t = to_plane;
        position = vec3(eye.x + t * d.x, params.level, eye.z + t * d.z);
        return false;
    }
    position = eye + t * d;
    if (params.refine_steps == 0u) return false;
    vec2 parameter = mesh_parameter;
    // A cell's chord lies under a crest (seen from above; over a trough from below), within the
    // sag of the surface: the first crossing lies within sag / |cos| of the mesh point along the
    // ray. Newton starts that far in front, so that it converges to the first crossing rather
    // than to the next crest's, and a solution outside that window is another crossing.
    const float back = min(params.mesh_sag / max(abs(dot(d, normal)), 0.05), 0.5 * t);
    const float slack = REFINEMENT_RELATIVE_TOLERANCE * (1.0 + t);
    const float t_min = t - back - slack, t_max = t + back + slack;
    float t_before = t - back;
    vec2 parameter_before = parameter - back * d.xz;
    vec3 refined_position, refined_normal;
    if (refine_water_hit(eye, d, t_min, t_max, t_before, parameter_before, refined_position, refined_normal) ||
        // Too far in front for Newton to converge in the steps given: from the mesh point itself.
        (back > 0.0 && refine_water_hit(eye, d, t_min, t_max, t, parameter, refined_position, refined_normal))) {
        position = refined_position;
        normal = refined_normal;
        return true;
    }
    return false;
}

#endif
