// Where a caustic photon meets the receivers under the water: the first surface
// along its refracted ray among the floor plane (exact) and the receiver meshes as the sun shadow
// map's beam half sees them (passes/receivers/sun_shadow.hpp: their depth along the flat-water refracted
// sun t0, clipped at the mean level), and whether objects above the water stop it before it
// enters. Included by the photon kernel in its VKWATER_SUN_SHADOW variant (scenes with meshes).
//
// The search (after Shah, Konttinen and Pattanaik's iterative estimate, de la Fuente 2011): along the
// photon's ray x(l) = entry + l t, the gap f(l) = (depth of the nearest receiver in x's column
// along t0) - (depth of x) is positive before the receiver and 0 on it. Starting from the floor
// (exact, f = 0 there unless a mesh is in front), one fixed-point step l += f / (t . t0), then
// secant steps, which are exact in one step for a planar receiver; it stops when |f| is below
// kReceiverTolerance of the map's texel, or after kReceiverSteps steps (the estimate then is the
// last one: near a silhouette the ray's column jumps between an object and what lies behind it).
#ifndef VKWATER_CAUSTIC_RECEIVER_HIT_GLSL
#define VKWATER_CAUSTIC_RECEIVER_HIT_GLSL

#include "caustics/caustic_photon.glsl"
#include "receivers/sun_shadow.glsl"

const int kReceiverSteps = 8;
const float kReceiverTolerance = 0.01;  // of the beam half's texel size
const float kNoReceiver = 3.0e38;

// Depth of the nearest mesh in x's column along t0, minus x's own depth (metres; kNoReceiver where
// the column holds no mesh or lies outside the map).
float mesh_gap(vec3 x) {
    const vec4 q = sun_shadow.beam.light_from_world * vec4(x, 1.0);
    const vec2 uv = vec2(0.5 + 0.5 * q.x, 0.5 - 0.5 * q.y);  // the pass flips y (sun_shadow.glsl)
    if (!(all(greaterThanEqual(uv, vec2(0.0))) && all(lessThan(uv, vec2(1.0))))) return kNoReceiver;
    const float size = sun_shadow.beam.params.z;
    const ivec2 texel = min(ivec2(uv * size), ivec2(size - 1.0)) + ivec2(int(size), 0);
    const float occluder = texelFetch(sun_shadow_map, texel, 0).r;
    if (!(occluder > 0.0)) return kNoReceiver;  // the clear: no mesh in this column
    return (q.z - occluder) * sun_shadow.beam.params.y;  // reversed depth: 1 nearest the water
}

// The receiver gap at x: the floor (t0 runs (x.y - floor) / -t0.y to it) or a mesh in front of it.
float receiver_gap(vec3 x, vec3 t0, float floor_y) {
    return min((x.y - floor_y) / -t0.y, mesh_gap(x));
}

// The path length from the photon's entry to its receiver, at most floor_length (the floor along
// the photon's own direction, where f = 0 exactly when no mesh is in front of it).
float receiver_path(CausticPhoton photon, vec3 t0, float floor_y, float floor_length) {
    if (sun_shadow.beam.params.w < 0.5) return floor_length;
    const vec3 p = photon.entry, t = photon.direction;
    const float tolerance = kReceiverTolerance * sun_shadow.beam.params.x;
    const float along = max(dot(t, t0), 0.1);  // the ray's advance in depth per metre (t near t0)
    float l0 = floor_length;
    float f0 = min(0.0, mesh_gap(p + l0 * t));
    if (f0 > -tolerance) return floor_length;
    float l1 = clamp(l0 + f0 / along, 0.0, floor_length);
    for (int step = 0; step < kReceiverSteps; ++step) {
        const float f1 = receiver_gap(p + l1 * t, t0, floor_y);
        if (abs(f1) <= tolerance) break;
        const float slope = (f1 - f0) / (l1 - l0);  // df/dl, about -(t . t0) on a receiver
        const float next = slope < -1e-3 ? l1 - f1 / slope : l1 + f1 / along;
        l0 = l1;
        f0 = f1;
        l1 = clamp(next, 0.0, floor_length);
        if (l1 == l0) break;
    }
    return l1;
}

// False when an object above the water shadows the photon's entry point (the map's sun half).
bool caustic_entry_lit(CausticPhoton photon, vec3 s) {
    return sun_visibility(photon.entry, max(-s.y, 1e-3)) > 0.5;
}

#endif
