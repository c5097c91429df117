// Light under the water for Lambertian receivers (docs/model.md sections 1 and 3), and the
// floor as the receiver that refracted view rays meet. The sun term is the caustic
// irradiance when VKWATER_CAUSTICS (the light-space map of passes/caustics/caustics_*, whose photons end on
// the floor and the receiver meshes) or VKWATER_CAMERA_CAUSTICS (the camera-space splats of
// passes/caustics/caustics_camera_splats.hpp) is defined and the flat-surface stand-in otherwise: one or
// the other at each point, never both.
#ifndef VKWATER_UNDERWATER_LIGHT_GLSL
#define VKWATER_UNDERWATER_LIGHT_GLSL

#include "common/frame_constants.glsl"
#include "common/lambert.glsl"
#include "receivers/floor_albedo.glsl"
#include "water/scene_optics.glsl"

#if defined(VKWATER_CAUSTICS)
// Bindings 4 and 5 of set 0 in every shader that lights receivers under the water.
#define CAUSTIC_SET 0
#define CAUSTIC_PARAMS_BINDING 4
#define CAUSTIC_MAP_BINDING 5
#include "caustics/caustic_lookup.glsl"
#elif defined(VKWATER_CAMERA_CAUSTICS)
#include "caustics/caustic_camera_lookup.glsl"  // bindings 4 and 5
#endif

bool point_under_water(vec3 p) {
    return frame.water.w > 0.5 && p.y < frame.water.x && abs(p.x) <= frame.water.z && abs(p.z) <= frame.water.z;
}

// The sun: the caustic irradiance (VKWATER_CAUSTICS: the light-space map; VKWATER_CAMERA_CAUSTICS:
// the camera-space splats, where the camera sees the point), or the stand-in through the flat
// surface, E_perp max(0, -t.N) exp(-sigma_t depth / cos_t); plus skylight pi L_sky_avg T_hemi
// exp(-sigma_t depth) (the vertical path of the model). With objects (VKWATER_SUN_SHADOW) the sun
// is shadowed along the refracted beam t (docs/model.md section 1):
// - the caustic photons were already stopped by objects above the water and ended on the first
//   receiver along their ray, so the light-space map needs only its depth test: a point behind the
//   surface the map sees along t (the shadow map's beam half) reads nothing; the camera-space
//   splats passed theirs against the camera's view when they were splatted;
// - the stand-in is shadowed by objects under the water along t (the beam half) and by objects
//   above it where the beam enters the flat surface (the sun half).
vec3 flat_surface_sun_under_water(vec3 p, vec3 normal, SceneOptics optics) {
    float depth = max(0.0, frame.water.x - p.y);
    float cos_receiver = max(0.0, -dot(optics.refracted_sun.xyz, normal));
    vec3 sun = optics.e_perp0.rgb * cos_receiver * exp(-frame.medium_sigma_t.rgb * (depth / optics.refracted_sun.w));
#ifdef VKWATER_SUN_SHADOW
    vec3 entry = p - (depth / optics.refracted_sun.w) * optics.refracted_sun.xyz;
    sun *= sun_visibility(entry, max(-frame.sun_direction.y, 1e-3));
    if (cos_receiver > 0.0) sun *= beam_visibility_under_water(p, cos_receiver);
#endif
    return sun;
}

vec3 sun_irradiance_under_water(vec3 p, vec3 normal, SceneOptics optics) {
#if defined(VKWATER_CAUSTICS)
    vec3 sun = caustic_irradiance(p, normal);
#ifdef VKWATER_SUN_SHADOW
    float cos_receiver = max(0.0, -dot(optics.refracted_sun.xyz, normal));
    if (cos_receiver > 0.0) sun *= beam_visibility_under_water(p, cos_receiver);
#endif
    return sun;
#elif defined(VKWATER_CAMERA_CAUSTICS)
    vec3 sun;
    return camera_caustic_irradiance(p, sun) ? sun : flat_surface_sun_under_water(p, normal, optics);
#else
    return flat_surface_sun_under_water(p, normal, optics);
#endif
}

vec3 receiver_irradiance_under_water(vec3 p, vec3 normal, SceneOptics optics) {
    float depth = max(0.0, frame.water.x - p.y);
    vec3 sky = PI * frame.sky_average.rgb * optics.transmission.x * exp(-frame.medium_sigma_t.rgb * depth);
    return sun_irradiance_under_water(p, normal, optics) + sky;
}

// The caustic layer's value at a receiver point (EXR channels caustic.R/G/B, as the reference
// writes them): the sun's irradiance there when it lies under the water, 0 above it.
vec3 caustic_layer_value(vec3 p, vec3 normal, SceneOptics optics) {
    return point_under_water(p) ? sun_irradiance_under_water(p, normal, optics) : vec3(0.0);
}

vec3 receiver_irradiance(vec3 p, vec3 normal, SceneOptics optics) {
    return point_under_water(p) ? receiver_irradiance_under_water(p, normal, optics)
                                : receiver_irradiance_above_water(p, normal);
}

// Where a ray from p in direction d (in the water) meets the floor plane, the floor's radiance
// there and its caustic layer value; false when it does not meet the floor within its extent.
bool floor_along(vec3 p, vec3 d, SceneOptics optics, out float distance_to_floor, out vec3 radiance,
                 out vec3 caustic) {
    radiance = vec3(0.0);
    caustic = vec3(0.0);
    distance_to_floor = 0.0;
    if (d.y > -1e-6) return false;
    distance_to_floor = (p.y - frame.floor_plane.x) / -d.y;
    vec3 hit = p + distance_to_floor * d;
    if (abs(hit.x) > frame.floor_plane.y || abs(hit.z) > frame.floor_plane.y) return false;
    const vec3 up = vec3(0.0, 1.0, 0.0);
    radiance = lambert_radiance(floor_albedo_at(hit.xz), receiver_irradiance(hit, up, optics));
#ifdef VKWATER_CAUSTIC_LAYER
    caustic = caustic_layer_value(hit, up, optics);
#endif
    return true;
}

#endif
