// Whether the sun reaches a point (docs/model.md section 1: the sun is shadowed by objects, above
// the water along s and below it along the refracted beam t), from the map of
// passes/receivers/sun_shadow.hpp: the point is projected into an orthographic light space and compared
// once with the nearest texel's occluder depth. The map's left half looks along s at every
// object; its right half (scenes with water) along the flat surface's refracted beam t at the
// objects under the water. Bindings 6 (the D32 map, read with texelFetch: no filtering, one
// compare) and 7 (the SunShadowSpace block) of set 0, in every shader compiled with
// VKWATER_SUN_SHADOW.
#ifndef VKWATER_SUN_SHADOW_GLSL
#define VKWATER_SUN_SHADOW_GLSL

// One half's orthographic projection. Its C++ type, and SunShadowSpace's, are generated once from
// common/shared_blocks.comp (passes/receivers/sun_shadow.hpp fills them).
struct ShadowProjection {
    mat4 light_from_world;  // world -> (x, y) in [-1, 1], z = 1 nearest the light, 0 farthest
    vec4 params;            // x: texel size, m; y: depth range, m; z: map size, texels (each half);
                            // w: 1 when the map has this half
};

layout(set = 0, binding = 7, std140) uniform SunShadowSpace {
    ShadowProjection sun;   // the left half, along s
    ShadowProjection beam;  // the right half, along the refracted beam t, for the objects under the water
} sun_shadow;
layout(set = 0, binding = 6) uniform sampler2D sun_shadow_map;

// 1 lit, 0 shadowed, by the half `half_index` of the map. cos_light = -l.N > 0 of the lit
// side. The bias covers what a single compare against the nearest texel gets wrong on the
// occluder's own surface: the texel's depth is the surface at the texel centre, up to about
// one texel away across the beam, where a surface tilted by theta from the beam's normal lies
// texel * tan(theta) deeper or shallower (the slope term), plus one texel for the
// rasteriser's rounding and the fp32 depth.
float shadow_map_visibility(mat4 light_from_world, vec4 params, int half_index, vec3 p, float cos_light) {
    const vec4 q = light_from_world * vec4(p, 1.0);
    // The pass's viewport flips y (row 0 is the top, at y = +1), as for every graphics pass.
    const vec2 uv = vec2(0.5 + 0.5 * q.x, 0.5 - 0.5 * q.y);
    if (any(lessThan(uv, vec2(0.0))) || any(greaterThanEqual(uv, vec2(1.0)))) return 1.0;  // outside: no occluder
    const float size = params.z;
    const ivec2 texel = min(ivec2(uv * size), ivec2(size - 1.0)) + ivec2(half_index * int(size), 0);
    const float occluder = texelFetch(sun_shadow_map, texel, 0).r;  // 0: nothing between the light and p
    const float range = params.y;
    // Distances along the beam from the map's near plane, metres.
    const float d_point = (1.0 - q.z) * range;
    const float d_occluder = (1.0 - occluder) * range;
    const float tan_theta = sqrt(max(0.0, 1.0 - cos_light * cos_light)) / max(cos_light, 0.05);
    const float bias = params.x * (1.0 + tan_theta);
    return d_occluder < d_point - bias ? 0.0 : 1.0;
}

// The direct sun at p above the water, or at the point where its refracted beam enters the water.
float sun_visibility(vec3 p, float cos_sun) {
    return shadow_map_visibility(sun_shadow.sun.light_from_world, sun_shadow.sun.params, 0, p, cos_sun);
}

// The refracted beam t (flat surface) at p under the water, by the objects under the water;
// cos_beam = -t.N of the lit side.
float beam_visibility_under_water(vec3 p, float cos_beam) {
    if (sun_shadow.beam.params.w < 0.5) return 1.0;
    return shadow_map_visibility(sun_shadow.beam.light_from_world, sun_shadow.beam.params, 1, p, cos_beam);
}

#endif
