#version 460
// The marched baseline of the godrays (passes/godrays/godrays_march.hpp): each godray pixel's view ray is
// followed through the water (from a camera in it: to the scene, and on along the surface's
// reflection where the ray meets the surface from below; from the air: along the ray refracted by
// the FLAT surface at the mean level) in N equal steps. Each step takes the sun's light at its
// midpoint, E_perp = e_perp0 exp(-sigma_t z / cos theta_t) times the caustic map's modulation
// (VKWATER_CAUSTICS: the map's irradiance where the refracted sun carries the point to the floor,
// over the flat water's irradiance there) and the sun shadow at the beam's entry point
// (VKWATER_SUN_SHADOW), and integrates the view path's transmittance over the step analytically:
//   L += sigma_s p(cos alpha) E_perp(x_mid) exp(-sigma_t s_i) Delta (1 - exp(-sigma_t Delta)) / (sigma_t Delta),
// so the error is that of the midpoint rule in the light alone (second order in Delta).
// Light reaches points whose refracted beam enters the surface within the water's extent and
// above max_depth, as the beams of the line method do.
#extension GL_GOOGLE_include_directive : require

#include "common/medium.glsl"
#include "godrays/godray_view.glsl"
#include "water/scene_optics.glsl"
#ifdef VKWATER_CAUSTICS
#define CAUSTIC_SET 0
#define CAUSTIC_PARAMS_BINDING 4
#define CAUSTIC_MAP_BINDING 5
#include "caustics/caustic_lookup.glsl"
#endif
#ifdef VKWATER_SUN_SHADOW
#include "receivers/sun_shadow.glsl"
#endif

layout(local_size_x = 8, local_size_y = 8) in;

layout(set = 0, binding = 1, std430) readonly buffer Optics { SceneOptics optics; };
layout(set = 0, binding = 2) uniform sampler2D view_depth;  // r: distance to the scene, g: 1 in the water
layout(set = 0, binding = 3, rgba32f) writeonly uniform image2D target;

// Its C++ type (GodrayMarchPush in passes/godrays/godrays_march.cpp) is generated from this shader.
layout(push_constant) uniform Push {
    uint steps;           // N per segment
    float max_amplitude;  // m: a bound on the waves' height, the margin of the surface's depth
    float max_depth;      // m below the mean level where the light stops
    float pad;
} pc;

const float kNegligible = 40.0;  // optical depth beyond which exp(-x) < 4.3e-18 adds nothing

// How far a ray from x (in the water, `before` metres of view path behind it) runs through lit
// water: until it leaves the water's box (the floor plane, the flat surface, the side walls), passes
// below max_depth (where the light stops), or both the sun's path and its own grow longer than
// kNegligible optical depths in every channel, so that the steps are spent where light is.
float lit_reach(vec3 x, vec3 v, float before) {
    const float level = frame.water.x, extent = frame.water.z;
    float reach = 1e30;
    if (v.y < 0.0) reach = (x.y - max(frame.floor_plane.x, level - pc.max_depth)) / -v.y;
    if (v.y > 0.0) reach = (level - x.y) / v.y;
    for (int axis = 0; axis < 3; axis += 2) {
        if (v[axis] > 0.0) reach = min(reach, (extent - x[axis]) / v[axis]);
        if (v[axis] < 0.0) reach = min(reach, (-extent - x[axis]) / v[axis]);
    }
    // The optical depth sigma_t (z / cos theta_t + before + s) grows at least as fast as sigma_t s.
    const vec3 sigma_t = frame.medium_sigma_t.rgb;
    const float slowest = min(sigma_t.r, min(sigma_t.g, sigma_t.b));
    const float cos_t = optics.refracted_sun.w;
    const float start = slowest * (max(0.0, level - x.y) / cos_t + before);
    const float rate = slowest * (1.0 + max(0.0, -v.y) / cos_t);
    if (rate > 0.0) reach = min(reach, max(0.0, (kNegligible - start) / rate));
    return max(reach, 0.0);
}

// The sun's light at x relative to the flat beam's e_perp0 exp(-sigma_t z / cos theta_t): 0 where the
// beam through x enters outside the water or x lies below max_depth; else the caustic modulation
// and the shadow of objects above the water.
vec3 light_factor(vec3 x, float z) {
    const vec3 t = optics.refracted_sun.xyz;
    const float cos_t = optics.refracted_sun.w;
    const vec3 entry = x - (z / cos_t) * t;
    if (z > pc.max_depth || any(greaterThan(abs(entry.xz), vec2(frame.water.z)))) return vec3(0.0);
    vec3 factor = vec3(1.0);
#ifdef VKWATER_CAUSTICS
    // The map holds the floor's irradiance through the real surface; over the flat surface's own,
    // it says how much the waves concentrate the beam that reaches x. Where the flat value
    // underflows the ratio means nothing: the flat beam stays.
    const float floor_y = frame.floor_plane.x;
    const vec3 on_floor = x + ((x.y - floor_y) / cos_t) * t;
    const vec3 flat_floor = optics.e_perp0.rgb * cos_t *
                            exp(-frame.medium_sigma_t.rgb * ((frame.water.x - floor_y) / cos_t));
    const vec3 mapped = caustic_irradiance(on_floor, vec3(0.0, 1.0, 0.0));
    for (int c = 0; c < 3; ++c) factor[c] = flat_floor[c] > 1e-30 ? mapped[c] / flat_floor[c] : 1.0;
#endif
#ifdef VKWATER_SUN_SHADOW
    factor *= sun_visibility(entry, max(-frame.sun_direction.y, 1e-3));
#endif
    return factor;
}

// In-scattered radiance arriving at `start` along -v from a view segment of length `len` in
// direction v, which the view ray reaches after `before` metres in the water.
vec3 march(vec3 start, vec3 v, float len, float before) {
    const vec3 sigma_t = frame.medium_sigma_t.rgb;
    const float step_length = len / float(pc.steps);
    const float cos_t = optics.refracted_sun.w;
    const vec3 per_step = step_length * one_minus_exp_over_x(sigma_t * step_length);
    vec3 sum = vec3(0.0);
    for (uint i = 0u; i < pc.steps; ++i) {
        const vec3 x = start + (float(i) + 0.5) * step_length * v;
        const float z = max(0.0, frame.water.x - x.y);
        // The sun's path to x and the view's path to the step's start, exponentiated once.
        const vec3 optical = sigma_t * (z / cos_t + before + float(i) * step_length);
        if (min(optical.r, min(optical.g, optical.b)) > kNegligible) continue;
        sum += light_factor(x, z) * exp(-optical) * per_step;
    }
    const float phase = henyey_greenstein(dot(optics.refracted_sun.xyz, -v), frame.medium_sigma_s.w);
    return frame.medium_sigma_s.rgb * phase * optics.e_perp0.rgb * sum;
}

vec3 from_the_water(vec3 eye, vec3 d, float scene_distance) {
    const float level = frame.water.x, n = frame.water.y;
    vec3 radiance = march(eye, d, min(scene_distance, lit_reach(eye, d, 0.0)), 0.0);
    // The surface seen from below: on along its reflection, weighted by R (1 outside Snell's window).
    if (d.y > 0.0 && eye.y < level) {
        const float to_surface = (level - eye.y) / d.y;
        const float margin = pc.max_amplitude / max(d.y, 0.05) + 1e-3 * to_surface;
        const vec3 q = eye + to_surface * d;
        if (scene_distance >= to_surface - margin && all(lessThanEqual(abs(q.xz), vec2(frame.water.z)))) {
            const vec3 reflected = vec3(d.x, -d.y, d.z);
            radiance += fresnel_exact(d.y, n, 1.0).R * march(q, reflected, lit_reach(q, reflected, to_surface), to_surface);
        }
    }
    return radiance;
}

vec3 from_the_air(vec3 eye, vec3 d, float scene_distance) {
    const float level = frame.water.x, n = frame.water.y;
    if (!(d.y < 0.0) || !(eye.y > level)) return vec3(0.0);
    const float to_surface = (eye.y - level) / -d.y;
    const vec3 q = eye + to_surface * d;
    const float margin = pc.max_amplitude / max(-d.y, 0.05) + 1e-3 * to_surface;
    if (to_surface > scene_distance + margin || any(greaterThan(abs(q.xz), vec2(frame.water.z)))) return vec3(0.0);
    vec3 v;
    refract_direction(d, vec3(0.0, 1.0, 0.0), 1.0 / n, v);  // never total reflection from the air
    return fresnel_exact(-d.y, 1.0, n).T / (n * n) * march(q, v, lit_reach(q, v, 0.0), 0.0);
}

void main() {
    const ivec2 g = ivec2(gl_GlobalInvocationID.xy);
    const ivec2 size = imageSize(target);
    if (any(greaterThanEqual(g, size))) return;
    const vec2 scene = texelFetch(view_depth, g, 0).rg;
    const vec3 eye = frame.camera_position.xyz;
    const vec3 d = godray_pixel_ray(vec2(g) + 0.5, vec2(size));
    const bool lit = frame.sun_direction.w > 0.5;
    const vec3 radiance = !lit ? vec3(0.0) : scene.y > 0.5 ? from_the_water(eye, d, scene.x) : from_the_air(eye, d, scene.x);
    imageStore(target, g, vec4(radiance, 1.0));
}
