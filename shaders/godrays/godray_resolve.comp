#version 460
// The fixed-point godray pyramids -> radiance at the godray resolution (passes/godrays/godrays_resolve.hpp):
// for each pyramid, LSB times the sum over the levels l of level l's counters upsampled bilinearly
// (godray_pyramid.glsl: level l's pixel centres sit at level-0 coordinates (i + 0.5) W / W_l; taps
// clamped to the level; bilinear weights sum to 1, so a level's mean is kept), times the phase
// function of the flat beam and the surface's weight for this pixel's own view direction:
//   in the water  L = p(v) S_straight + R p(v_mirrored) S_mirrored
//   from the air  L = T / n^2 p(v_refracted) S_straight
#extension GL_GOOGLE_include_directive : require
#extension GL_EXT_shader_explicit_arithmetic_types_int64 : require

#include "common/medium.glsl"
#include "godrays/godray_fixed_point.glsl"
#include "godrays/godray_pyramid.glsl"
#include "godrays/godray_view.glsl"

layout(local_size_x = 8, local_size_y = 8) in;

layout(set = 0, binding = 1, std430) readonly buffer Radiance { uint64_t radiance[]; };
layout(set = 0, binding = 2) uniform sampler2D view_depth;  // g: 1 where the camera ray starts in the water
layout(set = 0, binding = 3, rgba32f) writeonly uniform image2D target;

layout(push_constant) uniform Push {
    int levels;
} pc;

vec3 counters(uint pixel) {
    const uint i = pixel * 3u;
    return vec3(float(radiance[i]), float(radiance[i + 1u]), float(radiance[i + 2u]));
}

// One pyramid, starting `base` pixels into the buffer, summed at level-0 pixel g.
vec3 collapse(uint base, ivec2 g, ivec2 size) {
    vec3 sum = counters(base + uint(g.y * size.x + g.x));
    uint offset = base + uint(size.x * size.y);
    for (int level = 1; level < pc.levels; ++level) {
        const ivec2 level_size = godray_level_size(size, level);
        const vec2 c = (vec2(g) + 0.5) * godray_level_scale(size, level) - 0.5;
        const vec2 corner0 = floor(c), f = c - corner0;
        for (int k = 0; k < 4; ++k) {
            const ivec2 corner = ivec2(k & 1, k >> 1);
            const ivec2 tap = clamp(ivec2(corner0) + corner, ivec2(0), level_size - 1);
            const float w = (corner.x == 1 ? f.x : 1.0 - f.x) * (corner.y == 1 ? f.y : 1.0 - f.y);
            if (w > 0.0) sum += w * counters(offset + uint(tap.y * level_size.x + tap.x));
        }
        offset += uint(level_size.x * level_size.y);
    }
    return sum;
}

// The flat beam's phase times the surface's weight for this pixel in the view `kind`.
float angular(uint kind, vec3 d, vec3 flat_sun) {
    vec3 v;
    float weight;
    godray_pixel_view(kind, d, v, weight);
    return weight > 0.0 ? weight * henyey_greenstein(dot(flat_sun, -v), frame.medium_sigma_s.w) : 0.0;
}

void main() {
    const ivec2 g = ivec2(gl_GlobalInvocationID.xy);
    const ivec2 size = imageSize(target);
    if (any(greaterThanEqual(g, size))) return;
    const vec3 d = godray_pixel_ray(vec2(g) + 0.5, vec2(size));
    const vec3 flat_sun = godray_flat_refracted_sun();
    const uint pyramid = godray_level_offset(size, pc.levels);
    vec3 radiance;
    if (texelFetch(view_depth, g, 0).g > 0.5) {
        radiance = angular(kGodrayViewDirect, d, flat_sun) * collapse(uint(kGodrayStraight) * pyramid, g, size);
        const float mirrored = angular(kGodrayViewMirrored, d, flat_sun);
        if (mirrored > 0.0) radiance += mirrored * collapse(uint(kGodrayMirrored) * pyramid, g, size);
    } else {
        radiance = angular(kGodrayViewRefracted, d, flat_sun) * collapse(uint(kGodrayStraight) * pyramid, g, size);
    }
    imageStore(target, g, vec4(radiance * godray_lsb(), 1.0));
}
