// The water surface recovered per pixel from the mesh it is drawn with: the first crossing of
// the view ray with the displaced surface P(x) of the scene's wave model, found by Newton's
// method from the rasterised mesh point (docs/techniques/water_surface.md). The mesh
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
// 1: the water is drawn from the screen's grid (water/water_surface_screen.vert), whose cells can
// be coarse: the march for the first crossing and the square's edge per pixel are compiled in.
// 0: the uniform mesh, whose cells are fine enough for Newton alone, compiled without them
// (llvmpipe would run them masked for every pixel: docs/lavapipe.md).
layout(constant_id = 1) const uint WATER_SCREEN_GRID = 0u;
// 2: infinite water, drawn from the screen's grid (params.half_extent is then the square the
// camera can see), with its far field compiled in (water_in_far_field).
const bool WATER_INFINITE = WATER_SCREEN_GRID == 2u;

// Infinite water's far field (docs/model.md section 1, "Infinite water"): a ray whose crossing
// with the mean level lies farther than params.far_field from the eye, horizontally, meets the
// level there, flat; the waves are traced no farther. True with that crossing's ray parameter.
bool water_in_far_field(vec3 eye, vec3 d, out float t) {
    t = (params.level - eye.y) / d.y;
    return WATER_INFINITE && t > 0.0 && !isinf(t) && t * length(d.xz) > params.far_field;
}

// A converged crossing misses the surface by at most this times (1 + t) metres: about ten fp32
// ulps of the positions involved (P and eye + t d are sums of terms of magnitude t and |eye|).
const float REFINEMENT_RELATIVE_TOLERANCE = 1e-5;

// A bound on |surface height - level|: the push constant's (the CPU's, good at every time), or for
// the FFT ocean the largest |h| over its nodes this frame (water/ocean_height_bound.comp), which
// bounds its bilinear surface exactly and is several times smaller. The margin covers the fp32
// roundings of mix() and of level + h.
float water_height_bound() {
    if (WATER_SURFACE_MODEL != WATER_SURFACE_OCEAN) return params.amplitude;
    const float largest = grids[2u * params.ocean_n * params.ocean_n].x;
    return min(params.amplitude, largest * (1.0 + 1e-6) + 4.0 * 1.2e-7 * (abs(params.level) + largest));
}

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

// Windows shorter than this many march steps (half the shortest wavelength) hold at most one
// crest's crossings, where Newton from the window's front finds the first: the march runs first
// only over longer ones (and after Newton has failed over any).
const float REFINEMENT_MARCH_WINDOW = 4.0;

// The march's longest run: beyond it the steps grow (a ray that skims the surface for many
// wavelengths, near the horizon).
const uint REFINEMENT_MAX_MARCH_STEPS = 64u;

// Halvings of the march's bracket before Newton takes over: a step of an eighth of a wavelength
// becomes 1/128 of one, close enough for Newton at grazing angles, where the Jacobian is nearly
// singular and a step's worth of start can send it to another crossing.
const uint REFINEMENT_BISECTIONS = 4u;
// Where Newton still fails (at a Gerstner cusp, whose Jacobian is singular) the bracket is
// halved this many times more: 2^-16 of the step, below the acceptance tolerance for the
// steps here (a step of 0.1 m becomes 1.5 um).
const uint REFINEMENT_FINAL_BISECTIONS = 12u;

// A stretch of the view ray that holds its first crossing with the surface: t_front before it
// (the ray on its starting side, over the parameter x_front), t_after past it.
struct RayBracket {
    float t_front, t_after;
    vec2 x_front;
    vec2 shift;  // the surface's horizontal displacement at the last point evaluated
    bool start_above;
};

// Whether eye + s d lies above the surface: its height over P(x) at x = (eye + s d).xz less the
// horizontal displacement `shift` (exact for heightfields, close for Gerstner waves and the choppy
// ocean, whose displacement changes little over a step), which it updates to the one at x.
bool ray_point_above(vec3 eye, vec3 d, float s, inout vec2 shift, out vec2 x, out float height) {
    const vec3 q = eye + s * d;
    x = q.xz - shift;
    vec3 p, dP_du, dP_dv;
    water_surface_at(x, p, dP_du, dP_dv);
    shift = p.xz - x;
    height = q.y - p.y;
    return height > 0.0;
}

// Marches [t_lo, t_hi] for the first change of side. True with the step that holds it. Where
// the surface's slope has a bound (params.slope_bound > 0), the ray's height h over the surface
// changes by at most |d.y| + slope_bound |d.xz| per unit of t, so a step of h over that cannot
// pass a crossing: the steps shrink only where the ray skims the surface, down to half a march
// step. Without a bound, `steps` equal steps.
bool march_to_first_crossing(vec3 eye, vec3 d, float t_lo, float t_hi, uint steps, out RayBracket bracket) {
    const float fixed_step = (t_hi - t_lo) / float(steps);
    // Half a march step at the least (a sixteenth of the shortest wavelength): a crest thinner
    // than that along the ray may be passed, as a crossing that shallow changes the pixel little.
    const float least_step =
        max((t_hi - t_lo) / float(REFINEMENT_MAX_MARCH_STEPS), 0.5 * params.march_step / max(length(d.xz), 1e-3));
    const float height_rate = abs(d.y) + params.slope_bound * length(d.xz);
    vec2 x;
    float height;
    bracket.shift = vec2(0.0);
    ray_point_above(eye, d, t_lo, bracket.shift, x, height);  // the displacement at the start, for the first step
    bracket.start_above = ray_point_above(eye, d, t_lo, bracket.shift, x, height);
    bracket.t_front = t_lo;
    bracket.x_front = x;
    bracket.t_after = t_hi;
    float s = t_lo;
    for (uint i = 0u; i < REFINEMENT_MAX_MARCH_STEPS && s < t_hi; ++i) {
        const float step = params.slope_bound > 0.0 ? max(abs(height) / height_rate, least_step) : fixed_step;
        s = min(s + step, t_hi);
        if (ray_point_above(eye, d, s, bracket.shift, x, height) != bracket.start_above) {
            bracket.t_after = s;
            return true;
        }
        bracket.t_front = s;
        bracket.x_front = x;
    }
    return false;
}

void halve_bracket(vec3 eye, vec3 d, uint halvings, inout RayBracket bracket) {
    for (uint i = 0u; i < halvings; ++i) {
        const float middle = 0.5 * (bracket.t_front + bracket.t_after);
        vec2 x;
        float height;
        if (ray_point_above(eye, d, middle, bracket.shift, x, height) == bracket.start_above) {
            bracket.t_front = middle;
            bracket.x_front = x;
        } else {
            bracket.t_after = middle;
        }
    }
}

// The first crossing in [t_lo, t_hi] by the march: bracketed, halved, then Newton within a march
// step of the bracket; where Newton fails, the bracket halved down to the tolerance `slack`.
bool refine_by_march(vec3 eye, vec3 d, float t_lo, float t_hi, uint steps, float slack, out vec3 position,
                     out vec3 normal) {
    RayBracket bracket;
    if (!march_to_first_crossing(eye, d, t_lo, t_hi, steps, bracket)) return false;
    halve_bracket(eye, d, REFINEMENT_BISECTIONS, bracket);
    // The approximate heights may place the change of side up to a step from the crossing:
    // Newton's window keeps a march step on either side.
    const float step = max((t_hi - t_lo) / float(steps), bracket.t_after - bracket.t_front);
    float t = bracket.t_front;
    vec2 x = bracket.x_front;
    if (refine_water_hit(eye, d, bracket.t_front - step - slack, bracket.t_after + step + slack, t, x, position,
                         normal)) {
        return true;
    }
    halve_bracket(eye, d, REFINEMENT_FINAL_BISECTIONS, bracket);
    vec3 p, dP_du, dP_dv;
    water_surface_at(bracket.x_front, p, dP_du, dP_dv);
    if (!all(lessThanEqual(abs(bracket.x_front), vec2(params.half_extent))) ||
        !(distance(eye + bracket.t_front * d, p) <= slack)) {
        return false;
    }
    position = p;
    normal = water_normal(dP_du, dP_dv);
    return true;
}

// The surface point a pixel of the drawn mesh shows: the refined crossing of the pixel's view
// ray d (common/camera_ray.glsl: from the eye through the pixel's centre) with the surface, or,
// where refine_water_hit fails, the mesh's point moved onto that ray and the mesh's normal.
// mesh_sag bounds the drawn cell's distance from the surface (the vertex shader's).
// Returns whether it refined. The ray is the pixel's own rather than the direction to the
// rasterised mesh point: a varying interpolated over a large cell carries an error relative
// to the cell's coordinates (tens of metres), which turns the direction by about 1e-6 rad on
// some GPUs, and the shading amplifies that near the critical angle (Snell's window's edge).
// Flat water's crossing is the ray's with the plane y = level, exactly. `outside`: the point
// shown lies outside the water's square (the screen's grid reaches past it), so the pixel
// shows no water; never for the uniform mesh, which ends at the square's edge.
bool water_surface_of_pixel(vec3 eye, vec3 d, vec3 mesh_position, vec3 mesh_normal, vec2 mesh_parameter,
                            float mesh_sag, out vec3 position, out vec3 normal, out bool outside) {
    float to_level;
    if (water_in_far_field(eye, d, to_level)) {
        position = vec3(eye.x + to_level * d.x, params.level, eye.z + to_level * d.z);
        normal = vec3(0.0, 1.0, 0.0);
        outside = false;
        return true;
    }
    normal = normalize(mesh_normal);
    const bool may_pass_edge = WATER_SCREEN_GRID != 0u;
    outside = may_pass_edge && any(greaterThan(abs(mesh_parameter), vec2(params.half_extent)));
    float t = dot(mesh_position - eye, d);
    if (WATER_SURFACE_MODEL == WATER_SURFACE_FLAT) {
        const float to_plane = (params.level - eye.y) / d.y;
        if (to_plane > 0.0 && !isinf(to_plane)) t = to_plane;
        position = vec3(eye.x + t * d.x, params.level, eye.z + t * d.z);
        outside = may_pass_edge && any(greaterThan(abs(position.xz), vec2(params.half_extent)));
        return false;
    }
    position = eye + t * d;
    if (params.refine_steps == 0u) return false;
    vec2 parameter = mesh_parameter;
    // A cell's chord lies under a crest (seen from above; over a trough from below), within the
    // sag of the surface: the first crossing lies within sag / |cos| of the mesh point along the
    // ray. Newton starts that far in front, so that it converges to the first crossing rather
    // than to the next crest's, and a solution outside that window is another crossing.
    // (On the screen's grid the level's cosine too: a coarse cell's normal can lean toward the ray.)
    const float cosine = WATER_SCREEN_GRID != 0u ? min(abs(dot(d, normal)), abs(d.y)) : abs(dot(d, normal));
    const float back = min(mesh_sag / max(cosine, 0.05), 0.5 * t);
    const float slack = REFINEMENT_RELATIVE_TOLERANCE * (1.0 + t);
    const float t_min = t - back - slack, t_max = t + back + slack;
    float t_before = t - back;
    vec2 parameter_before = parameter - back * d.xz;
    vec3 refined_position, refined_normal;
    // On the screen's grid, a window longer than half the shortest wavelength (a coarse cell
    // seen at a grazing angle) can hold several crossings, and Newton from its front may land on
    // any of them: march it for the first change of side, then refine within that step. The
    // march runs over the part of the window inside the slab |y - level| <= the height bound, which
    // holds both the mesh's point and every crossing.
    const float slab = water_height_bound();
    const float to_top = (params.level + slab - eye.y) / d.y;
    const float to_bottom = (params.level - slab - eye.y) / d.y;
    const float march_lo = max(t - back, min(to_top, to_bottom)), march_hi = min(t + back, max(to_top, to_bottom));
    const float window_run = (march_hi - march_lo) * length(d.xz);
    const bool can_march = WATER_SCREEN_GRID != 0u && params.march_step > 0.0 && march_hi > march_lo;
    const uint steps = can_march ? clamp(uint(ceil(window_run / params.march_step)), 2u, REFINEMENT_MAX_MARCH_STEPS) : 0u;
    const bool march_first = can_march && window_run > REFINEMENT_MARCH_WINDOW * params.march_step;
    if ((march_first && refine_by_march(eye, d, march_lo, march_hi, steps, slack, refined_position, refined_normal)) ||
        refine_water_hit(eye, d, t_min, t_max, t_before, parameter_before, refined_position, refined_normal) ||
        // Too far in front for Newton to converge in the steps given: from the mesh point itself.
        (back > 0.0 && refine_water_hit(eye, d, t_min, t_max, t, parameter, refined_position, refined_normal)) ||
        // A short window where Newton failed from both ends: the march, which brackets.
        (can_march && !march_first &&
         refine_by_march(eye, d, march_lo, march_hi, steps, slack, refined_position, refined_normal))) {
        position = refined_position;
        normal = refined_normal;
        outside = false;
        return true;
    }
    return false;
}

#endif
