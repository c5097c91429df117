// The light-space frame of the caustic map, computed on the CPU in double by
// passes/caustics/caustics_light_space.cpp (fit_caustic_map) and handed to every caustic kernel and to
// the lookup: orthographic along the flat-water refracted sun t, so a world point P lands at the
// continuous texel coordinate (dot(P - origin, u_axis), dot(P - origin, v_axis)), texel centres
// at integer + 0.5. Photons and receivers share this one projection, so a receiver reads
// exactly the texels its own photons were splatted into.
#ifndef VKWATER_CAUSTIC_LIGHT_SPACE_GLSL
#define VKWATER_CAUSTIC_LIGHT_SPACE_GLSL

// std140 and std430 lay this out identically (four vec4). Its C++ mirror is generated from
// common/shared_blocks.comp (CausticLightSpacePush in passes/caustics/caustics_light_space.hpp).
struct CausticLightSpace {
    vec4 origin;  // xyz: a world point at texel coordinate (0, 0) and depth 0; w: floor height y
    vec4 u_axis;  // xyz: u / (texel size along u), 1/m; w: map width W in texels
    vec4 v_axis;  // xyz: v / (texel size along v), 1/m; w: map height H in texels
    vec4 sun;     // xyz: unit direction the sunlight travels (down); w: index of refraction n
};

vec2 caustic_texel_coord(vec3 p, CausticLightSpace space) {
    const vec3 r = p - space.origin.xyz;
    return vec2(dot(r, space.u_axis.xyz), dot(r, space.v_axis.xyz));
}

// The map's projection direction t (unit, pointing down: the refracted sun always does).
vec3 caustic_map_direction(CausticLightSpace space) {
    const vec3 t = normalize(cross(space.u_axis.xyz, space.v_axis.xyz));
    return t.y > 0.0 ? -t : t;
}

#endif
