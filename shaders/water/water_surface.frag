#version 450
#extension GL_GOOGLE_include_directive : require
// The water surface with the simplest correct lookups (docs/model.md sections 1-3, 6, 7):
// exact Fresnel and total internal reflection, the sky and the sun's disk in reflection,
// refraction down to the floor plane, radiance scaled by n^2 across the surface, sigma_t
// attenuation and single scattering along every path in the water. From above and, for
// a camera in the water, from below (Snell's window). Variants (shaders/CMakeLists.txt):
// VKWATER_PER_PIXEL_MEDIUM (the stencil split's mask), VKWATER_CAUSTICS (the floor seen
// through the water reads the caustic map) and VKWATER_SCENE_VIEWS (reflected and refracted
// rays also meet the receiver meshes, through the scene views: water/scene_lookup.glsl;
// the floor and the sky stay exact). VKWATER_CAUSTIC_LAYER adds a second output: the sun's
// irradiance on the receiver the refracted view ray meets (0 for a camera in the water, whose
// pixels on the surface see the air or a reflection), as the reference's caustic layer.
#include "common/camera_ray.glsl"
#include "common/fresnel.glsl"
#include "common/medium.glsl"
#include "common/sky.glsl"
#include "water/sun_glitter.glsl"
#include "water/camera_medium.glsl"
#include "water/surface_refinement.glsl"
#include "water/underwater_light.glsl"
#include "water/water_bottom.glsl"

#ifdef VKWATER_SCENE_VIEWS
#include "water/scene_lookup.glsl"
#endif

layout(set = 0, binding = 1, std430) readonly buffer Optics { SceneOptics optics; };

const uint SURFACE_FRESNEL_EXACT = 0u;
const uint SURFACE_FRESNEL_SCHLICK = 1u;
const uint SURFACE_FRESNEL_POWER = 2u;
// Specialization constants (passes/water/water_shading.cpp); constants 0 and 1 are the wave
// model's and the mesh's (water/surface_refinement.glsl), 8 the refraction view's second layer
// (water/scene_lookup.glsl). As constants, the paths a scene does
// not take are compiled out instead of run masked.
layout(constant_id = 2) const uint FRESNEL_MODEL = SURFACE_FRESNEL_EXACT;  // effects.water.fresnel
layout(constant_id = 3) const uint DEPTH_BLEND = 0u;        // 1: Optical Phenomena c. 2008's depth colour
layout(constant_id = 4) const uint REFLECTION_METHOD = 0u;  // SCENE_LOOKUP_*: 0 off, 1 projective, 2 screen-space
layout(constant_id = 5) const uint REFRACTION_METHOD = 0u;
// The camera's side of the surface when every pixel shares it (0 the air, 1 the water), or 2:
// per pixel, camera_in_water() (the stencil split's mask, or the frame constants).
layout(constant_id = 6) const uint CAMERA_SIDE = 2u;
bool eye_in_water() { return CAMERA_SIDE == 2u ? camera_in_water() : CAMERA_SIDE == 1u; }
layout(constant_id = 7) const uint GLITTER = 0u;  // effects.water.glitter: 1 the sun's glitter lobe

// The surface's Fresnel split as the scene chooses it (effects.water.fresnel): the exact equations
// (the model, docs/model.md section 2); Schlick's approximation; or Optical Phenomena c. 2008's power term
// F = (1 - E.N)^q with E.N the cosine on the incoming side, which knows no total internal
// reflection, so the exact form's is kept (R = 1 outside Snell's window from below).
Fresnel surface_fresnel(float cos_i, float n_i, float n_t) {
    Fresnel exact = fresnel_exact(cos_i, n_i, n_t);
    if (FRESNEL_MODEL == SURFACE_FRESNEL_SCHLICK) return fresnel_schlick(cos_i, n_i, n_t);
    if (FRESNEL_MODEL == SURFACE_FRESNEL_POWER && !exact.total_internal_reflection) {
        float r = pow(1.0 - clamp(cos_i, 0.0, 1.0), params.fresnel_power);
        return Fresnel(r, 1.0 - r, exact.cos_t, false);
    }
    return exact;
}

// Ojeda & Susín 2013's saving: a screen-space march is skipped for a ray whose Fresnel weight is
// below this (its object is then missed: an error of at most 1% of the object's radiance
// against the exact lookup behind it). Water's R is at least 0.02, so in practice it skips
// only refracted rays near grazing incidence.
const float SCREEN_SPACE_FRESNEL_SKIP = 0.01;

// The receiver mesh a reflected (or refracted) ray from p meets before `limit`, if any;
// `weight` is the ray's Fresnel weight (R or T).
// `object_caustic`: the caustic layer's value on it (refracted rays with VKWATER_CAUSTIC_LAYER; else 0).
bool object_along(bool reflected, vec3 p, vec3 d, float limit, float weight, out vec3 radiance,
                  out float distance_to_object, out vec3 object_caustic) {
    radiance = vec3(0.0);
    distance_to_object = 0.0;
    object_caustic = vec3(0.0);
#ifdef VKWATER_SCENE_VIEWS
    // The views keep the sides of the frame's camera medium; pixels whose ray starts on
    // the other side (the camera crossing the surface) keep the exact lookups alone.
    if (camera_in_water() != (frame.camera_medium.x > 0.5)) return false;
    SceneHit hit;
    uint method = reflected ? REFLECTION_METHOD : REFRACTION_METHOD;
    if (method == SCENE_LOOKUP_SCREEN_SPACE && weight < SCREEN_SPACE_FRESNEL_SKIP) return false;
    int steps = int(reflected ? params.reflection_steps : params.refraction_steps);
    if (scene_lookup(method, reflected, p, d, limit, steps, hit) && hit.distance < limit) {
        radiance = hit.radiance;
        distance_to_object = hit.distance;
#ifdef VKWATER_CAUSTIC_LAYER
        if (!reflected) object_caustic = refraction_view_caustic_at(hit);
#endif
        return true;
    }
#endif
    return false;
}

layout(location = 0) in vec3 in_position;
layout(location = 1) in vec3 in_normal;
layout(location = 2) in vec2 in_parameter;
layout(location = 3) in float in_mesh_sag;  // m: the drawn cell's distance from the surface, at most
layout(location = 0) out vec4 out_radiance;
#ifdef VKWATER_CAUSTIC_LAYER
layout(location = 1) out vec4 out_caustic;
#endif

// Radiance arriving at p along d inside the water: the floor or object it meets,
// attenuated, plus the sun's beam scattered along the way. `reflected`: d is the
// reflection of a ray from the water (else the refraction of one from the air).
// `caustic`: the caustic layer's value at what it meets (VKWATER_CAUSTIC_LAYER; else 0).
vec3 radiance_in_water(vec3 p, vec3 d, bool reflected, float weight, out float length_in_water, out vec3 caustic) {
    vec3 behind;
    bool floor_hit = floor_along(p, d, optics, length_in_water, behind, caustic);
    if (!floor_hit) length_in_water = 0.0;
    // Under infinite water a ray that meets no receiver runs on to the water's bottom, where
    // nothing is lit (water/water_bottom.glsl); elsewhere the scenes close their water with a
    // floor or walls, and such a ray leaves it.
    const float to_bottom = WATER_INFINITE ? run_to_water_bottom(p, d, params.bottom_y, params.far_field) : 0.0;
    vec3 object;
    float distance_to_object;
    vec3 object_caustic;
    if (object_along(reflected, p, d, floor_hit ? length_in_water : params.scene_size, weight, object,
                     distance_to_object, object_caustic)) {
        behind = object;
        length_in_water = distance_to_object;
        caustic = object_caustic;
    }
    if (DEPTH_BLEND != 0u && !reflected) {
        // Optical Phenomena c. 2008's depth colour in place of the medium along the refracted ray: what the ray
        // meets fades to the water's colour C_w by exp(-k d), d its length in the water (a ray
        // that meets nothing sees C_w).
        float a = floor_hit || length_in_water > 0.0 ? exp(-params.blend_k * length_in_water) : 0.0;
        return params.water_colour.rgb + a * (behind - params.water_colour.rgb);
    }
    if (!floor_hit && length_in_water == 0.0) length_in_water = max(to_bottom, 0.0);
    return water_path_radiance(analytic_inscatter_sigma_s(), frame.medium_sigma_t.rgb, frame.medium_sigma_s.w,
                               max(0.0, frame.water.x - p.y), length_in_water, d, optics.refracted_sun.xyz,
                               optics.e_perp0.rgb, behind);
}

// What a ray from the water's surface into the air brings back: the receiver it meets, else the sky,
// with the sun's disk unless the glitter stands for it (`with_sun_disk`); `met_object` tells which.
vec3 radiance_in_air_along(vec3 p, vec3 d, float weight, bool with_sun_disk, out bool met_object) {
    vec3 object;
    float distance_to_object;
    vec3 object_caustic;
    met_object = object_along(true, p, d, params.scene_size, weight, object, distance_to_object, object_caustic);
    if (met_object) return object;
    return with_sun_disk ? sky_radiance(d) : sky_base_radiance(d);
}

// A ray reflected from the air below the horizon meets the water again, not the sky's `ground`.
// The stated approximation (docs/model.md section 1, "Reflections below the horizon"): it meets,
// at the mean level, the mirror image of the face that turned it down (the wave's other flank,
// tilted toward the ray as far as the first tilts away from the eye), or the flat level where that
// face would not send it back up. There the Fresnel split at its own angle sends R of it up to the
// sky or a receiver and lets T of the water's light out, taken to be what the pixel's own refracted
// ray brings (`water_seen_from_air`, already divided by n^2): the two crossings lie within a
// wavelength of each other. The reference traces the same path against the true surface.
vec3 water_seen_below_horizon(vec3 p, vec3 d, vec3 normal, float weight, vec3 water_seen_from_air) {
    const float n = frame.water.y, level = frame.water.x;
    const vec3 q = p.y > level ? p + ((level - p.y) / d.y) * d : p;
    vec3 facing = vec3(-normal.x, normal.y, -normal.z);
    if (!(dot(d, facing) < 0.0) || reflect(d, facing).y < 0.0) facing = vec3(0.0, 1.0, 0.0);
    const Fresnel f = surface_fresnel(-dot(d, facing), 1.0, n);
    bool met_object;
    return f.R * radiance_in_air_along(q, reflect(d, facing), weight * f.R, true, met_object) +
           f.T * water_seen_from_air;
}

void main() {
    vec3 eye = frame.camera_position.xyz;
    const vec3 v = camera_ray_direction(gl_FragCoord.xy);  // the pixel's view ray
    // The exact surface where the view ray crosses it; the mesh's point (moved onto the ray) and
    // normal where Newton's method does not converge (water/surface_refinement.glsl).
    vec3 p, normal;  // normal: toward the air
    bool outside;
    water_surface_of_pixel(eye, v, in_position, in_normal, in_parameter, in_mesh_sag, p, normal, outside);
    if (WATER_SCREEN_GRID != 0u && outside) discard;
    float n = frame.water.y;
    // The slopes this pixel cannot resolve (their screen derivatives need uniform control flow).
    const vec3 unresolved = GLITTER != 0u ? pixel_unresolved_slopes(p) : vec3(0.0);

    if (!eye_in_water()) {
        // From the air. A wave's back face seen from above keeps a grazing cosine of 0.
        Fresnel f = surface_fresnel(max(0.0, -dot(v, normal)), 1.0, n);
        vec3 refracted_direction;
        vec3 transmitted = vec3(0.0);
        vec3 caustic = vec3(0.0);
        if (refract_direction(v, normal, 1.0 / n, refracted_direction)) {
            float refracted_length;
            transmitted = radiance_in_water(p, refracted_direction, false, f.T, refracted_length, caustic) / (n * n);
#ifdef VKWATER_SCENE_VIEWS
            // Ojeda & Susín 2013: in very shallow water the screen-space refraction fades to what lies
            // straight behind the surface, by the water's depth along the view ray (a chosen
            // approximation: it hides the march's misses where the water thins out; off by default).
            if (REFRACTION_METHOD == SCENE_LOOKUP_SCREEN_SPACE && params.shallow_blend > 0.0) {
                float direct_length;
                vec3 direct_caustic;
                vec3 direct = radiance_in_water(p, v, false, f.T, direct_length, direct_caustic) / (n * n);
                transmitted = mix(direct, transmitted, clamp(direct_length / params.shallow_blend, 0.0, 1.0));
            }
#endif
        }
        // The sun's glitter stands for its disk in reflections where the unresolved slopes spread it
        // more than the disk (water/sun_glitter.glsl); a reflected ray that meets a receiver hides it.
        const bool glitter = GLITTER != 0u && glitter_replaces_disk(unresolved, false, n);
        vec3 reflected_direction = reflect(v, normal);
        bool met_object = false;
        vec3 reflected = reflected_direction.y < 0.0
                             ? water_seen_below_horizon(p, reflected_direction, normal, f.R, transmitted)
                             : radiance_in_air_along(p, reflected_direction, f.R, !glitter, met_object);
        vec3 sun = vec3(0.0);
        if (glitter && !met_object) {
            const float facet_cos = max(0.0, dot(-v, glitter_half_vector(-v, -frame.sun_direction.xyz)));
            sun = sun_glitter_radiance(-v, normal, unresolved, surface_fresnel(facet_cos, 1.0, n).R);
        }
        out_radiance = vec4(f.R * reflected + f.T * transmitted + sun, 1.0);
#ifdef VKWATER_CAUSTIC_LAYER
        out_caustic = vec4(caustic, 1.0);
#endif
        return;
    }
    // From the water: total internal reflection outside Snell's window.
    vec3 water_side = -normal;
    Fresnel f = surface_fresnel(max(0.0, dot(v, normal)), n, 1.0);
    float reflected_length;
    vec3 reflected_caustic;  // not in the layer: the reference records the first receiver only
    vec3 at_surface =
        f.R * radiance_in_water(p, reflect(v, water_side), true, f.R, reflected_length, reflected_caustic);
    // Through Snell's window the refracted sun glitters too: the lobe of the facets' transmission
    // stands for the disk where the unresolved slopes spread it more (water/sun_glitter.glsl). It
    // reaches the eye even where the pixel's own normal reflects the view ray totally.
    const bool glitter = GLITTER != 0u && glitter_replaces_disk(unresolved, true, n);
    bool met_object = false;
    vec3 to_air;
    if (!f.total_internal_reflection && refract_direction(v, water_side, n, to_air)) {
        vec3 above = glitter ? sky_base_radiance(to_air) : sky_radiance(to_air);
        vec3 object;
        float distance_to_object;
        vec3 object_caustic;
        met_object = object_along(false, p, to_air, params.scene_size, f.T, object, distance_to_object, object_caustic);
        if (met_object) above = object;
        at_surface += f.T * n * n * above;
    }
    if (glitter && !met_object) {
        const vec3 to_sun = -frame.sun_direction.xyz;
        const float facet_cos = max(0.0, dot(to_sun, glitter_refraction_half_vector(-v, to_sun, n)));
        at_surface += refracted_sun_glitter_radiance(-v, normal, unresolved, n, surface_fresnel(facet_cos, 1.0, n).T);
    }
    float camera_depth = max(0.0, frame.water.x - eye.y);
    out_radiance = vec4(water_path_radiance(analytic_inscatter_sigma_s(), frame.medium_sigma_t.rgb,
                                            frame.medium_sigma_s.w, camera_depth, distance(eye, p), v,
                                            optics.refracted_sun.xyz, optics.e_perp0.rgb, at_surface),
                        1.0);
#ifdef VKWATER_CAUSTIC_LAYER
    out_caustic = vec4(0.0);
#endif
}
