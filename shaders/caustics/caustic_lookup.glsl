// The caustic irradiance a receiver reads: the point is projected along the
// map's direction t (the flat-water refracted sun) into the light-space map that
// passes/caustics/caustics_resolve.hpp writes (irradiance on a plane normal to t, E_perp = Phi_texel /
// A_ls), bilinearly between texel centres, and converted to the receiver:
// E = E_perp max(0, -t . N_r) (= Phi_texel max(0, -t . N_r) / A_ls). A face turned away from t
// gets 0 (its texels belong to the lit face in front of it). Points outside the map get 0: no
// water lies between them and the sun. The depth test (is the point the surface the map sees
// along t, or behind it?) is the caller's: beam_visibility_under_water of
// receivers/sun_shadow.glsl, the map the photons were traced against.
//
// The includer chooses where the map lives, before including this file:
//   #define CAUSTIC_SET 0
//   #define CAUSTIC_PARAMS_BINDING 3   // uniform, the CausticLightSpace block (std140)
//   #define CAUSTIC_MAP_BINDING 4      // sampler2D, the resolved RGBA32F map (read with texelFetch)
#ifndef VKWATER_CAUSTIC_LOOKUP_GLSL
#define VKWATER_CAUSTIC_LOOKUP_GLSL

#if !defined(CAUSTIC_SET) || !defined(CAUSTIC_PARAMS_BINDING) || !defined(CAUSTIC_MAP_BINDING)
#error "define CAUSTIC_SET, CAUSTIC_PARAMS_BINDING and CAUSTIC_MAP_BINDING before including caustic_lookup.glsl"
#endif

#include "caustics/caustic_light_space.glsl"

layout(set = CAUSTIC_SET, binding = CAUSTIC_PARAMS_BINDING, std140) uniform CausticMapBlock {
    CausticLightSpace caustic_space;
};
layout(set = CAUSTIC_SET, binding = CAUSTIC_MAP_BINDING) uniform sampler2D caustic_map;

vec3 caustic_map_texel(ivec2 texel) {
    const ivec2 size = ivec2(caustic_space.u_axis.w, caustic_space.v_axis.w);
    if (any(lessThan(texel, ivec2(0))) || any(greaterThanEqual(texel, size))) return vec3(0.0);
    return texelFetch(caustic_map, texel, 0).rgb;
}

vec3 caustic_irradiance(vec3 world_position, vec3 normal) {
    // Clamped first: int() of a coordinate far off the map would be undefined.
    const vec2 size = vec2(caustic_space.u_axis.w, caustic_space.v_axis.w);
    const vec2 c = clamp(caustic_texel_coord(world_position, caustic_space) - 0.5, vec2(-2.0), size + 1.0);
    const vec2 base = floor(c);
    const vec2 f = c - base;
    const ivec2 t = ivec2(base);
    const vec3 e = mix(mix(caustic_map_texel(t), caustic_map_texel(t + ivec2(1, 0)), f.x),
                       mix(caustic_map_texel(t + ivec2(0, 1)), caustic_map_texel(t + ivec2(1, 1)), f.x), f.y);
    return e * max(0.0, -dot(caustic_map_direction(caustic_space), normal));
}

#endif
