// Whether the direct sun reaches a point above the water (PHYSICS.md section 1: the sun is
// shadowed by objects), from the map of passes/sun_shadow.hpp: the point is projected into the
// sun's orthographic light space and compared once with the nearest texel's occluder depth.
// Bindings 6 (the D32 map, read with texelFetch: no filtering, one compare) and 7 (the
// SunShadowSpace block) of set 0, in every shader compiled with VKWATER_SUN_SHADOW.
#ifndef VKWATER_SUN_SHADOW_GLSL
#define VKWATER_SUN_SHADOW_GLSL

// Mirrored by SunShadowSpace in passes/sun_shadow.hpp.
layout(set = 0, binding = 7, std140) uniform SunShadowSpace {
    mat4 light_from_world;  // world -> (x, y) in [-1, 1], z = 1 nearest the sun, 0 farthest
    vec4 params;            // x: texel size, m; y: depth range, m; z: map size, texels
} sun_shadow;
layout(set = 0, binding = 6) uniform sampler2D sun_shadow_map;

// 1 lit, 0 shadowed. cos_sun = -s.N > 0 of the lit side. The bias covers what a single compare
// against the nearest texel gets wrong on the occluder's own surface: the texel's depth is the
// surface at the texel centre, up to about one texel away across the beam, where a surface
// tilted by theta from the beam's normal lies texel * tan(theta) deeper or shallower (the slope
// term), plus one texel for the rasteriser's rounding and the fp32 depth.
float sun_visibility(vec3 p, float cos_sun) {
    const vec4 q = sun_shadow.light_from_world * vec4(p, 1.0);
    // The pass's viewport flips y (row 0 is the top, at y = +1), as for every graphics pass.
    const vec2 uv = vec2(0.5 + 0.5 * q.x, 0.5 - 0.5 * q.y);
    if (any(lessThan(uv, vec2(0.0))) || any(greaterThanEqual(uv, vec2(1.0)))) return 1.0;  // outside: no occluder
    const float size = sun_shadow.params.z;
    const ivec2 texel = min(ivec2(uv * size), ivec2(size - 1.0));
    const float occluder = texelFetch(sun_shadow_map, texel, 0).r;  // 0: nothing between the sun and p
    const float range = sun_shadow.params.y;
    // Distances along the beam from the map's near plane, metres.
    const float d_point = (1.0 - q.z) * range;
    const float d_occluder = (1.0 - occluder) * range;
    const float tan_theta = sqrt(max(0.0, 1.0 - cos_sun * cos_sun)) / max(cos_sun, 0.05);
    const float bias = sun_shadow.params.x * (1.0 + tan_theta);
    return d_occluder < d_point - bias ? 0.0 : 1.0;
}

#endif
