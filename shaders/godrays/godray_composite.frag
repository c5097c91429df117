#version 450
// The godrays onto the HDR colour (passes/godrays/godrays_composite.hpp), drawn with additive blending over
// a full-screen triangle: the godray image upsampled to the output depth-aware. Of the four godray
// pixels around this pixel's position, those whose scene distance matches this pixel's within 5%
// are blended bilinearly; where none does (a depth edge narrower than a godray pixel), the one
// nearest in distance is taken. At the output's own resolution this is exactly a copy.
// VKWATER_INSCATTER_LAYER writes the same radiance to a second target, the in-scatter layer.
#extension GL_GOOGLE_include_directive : require

#include "godrays/godray_view.glsl"

layout(set = 0, binding = 1) uniform sampler2D godrays;      // radiance, godray resolution
layout(set = 0, binding = 2) uniform sampler2D view_depth;   // r: distance to the scene, godray resolution
layout(set = 0, binding = 3) uniform sampler2D scene_depth;  // D32, output resolution

layout(location = 0) out vec4 out_radiance;
#ifdef VKWATER_INSCATTER_LAYER
layout(location = 1) out vec4 out_inscatter;
#endif

const float kSameSurface = 0.05;

void main() {
    const ivec2 size = textureSize(godrays, 0);
    const vec2 full = vec2(textureSize(scene_depth, 0));
    const float here = godray_scene_distance(gl_FragCoord.xy, full,
                                             texelFetch(scene_depth, ivec2(gl_FragCoord.xy), 0).r);
    const vec2 c = gl_FragCoord.xy * (vec2(size) / full) - 0.5;
    const vec2 base = floor(c), f = c - base;
    vec3 sum = vec3(0.0), nearest = vec3(0.0);
    float weight = 0.0, nearest_gap = 1e38;
    for (int k = 0; k < 4; ++k) {
        const ivec2 offset = ivec2(k & 1, k >> 1);
        const ivec2 tap = clamp(ivec2(base) + offset, ivec2(0), size - 1);
        const float bilinear = (offset.x == 1 ? f.x : 1.0 - f.x) * (offset.y == 1 ? f.y : 1.0 - f.y);
        const float d = texelFetch(view_depth, tap, 0).r;
        const vec3 radiance = texelFetch(godrays, tap, 0).rgb;
        const float gap = abs(d - here);
        if (gap < nearest_gap) {
            nearest_gap = gap;
            nearest = radiance;
        }
        if (bilinear > 0.0 && gap <= kSameSurface * max(d, here)) {
            sum += bilinear * radiance;
            weight += bilinear;
        }
    }
    out_radiance = vec4(weight > 0.0 ? sum / weight : nearest, 0.0);
#ifdef VKWATER_INSCATTER_LAYER
    out_inscatter = out_radiance;
#endif
}
