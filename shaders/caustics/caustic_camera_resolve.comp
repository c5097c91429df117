#version 460
// Camera-space caustic flux -> irradiance on the receiver each pixel of the receivers' view shows
// (passes/caustics/caustics_camera_splats.hpp): at level 0, E = Phi_pixel |v . N_r| / (s^2 Omega_pix), with v
// and s the direction and distance from the eye to the receiver point, N_r its normal and Omega_pix
// the pixel's solid angle (caustic_camera_view.glsl: Phi over the area the pixel sees of the
// receiver's plane); plus each coarser level's flux over its pixels' areas on the same plane,
// interpolated bilinearly over the level pixels that show this receiver's plane (the splats' own
// plane test; weights renormalised). Writes (E, s); (0, 0) where no receiver is seen.
#extension GL_GOOGLE_include_directive : require
#extension GL_EXT_shader_explicit_arithmetic_types_int64 : require

#include "caustics/caustic_camera_view.glsl"  // binding 0: the frame constants

layout(local_size_x = 8, local_size_y = 8) in;

layout(set = 0, binding = 1, std430) readonly buffer Flux { uint64_t flux[]; };
layout(set = 0, binding = 2) uniform sampler2D receivers;
layout(set = 0, binding = 3, rgba32f) writeonly uniform image2D irradiance;

layout(push_constant) uniform Push {
    vec4 lsb;  // rgb: W per fixed-point unit, per channel
    uint width;
    uint height;
} pc;

vec3 level_flux(uint base, ivec2 level_size, ivec2 t) {
    const uint i = (base + uint(t.y) * uint(level_size.x) + uint(t.x)) * 3u;
    return vec3(float(flux[i]), float(flux[i + 1u]), float(flux[i + 2u])) * pc.lsb.rgb;
}

void main() {
    const uvec2 g = gl_GlobalInvocationID.xy;
    if (g.x >= pc.width || g.y >= pc.height) return;
    const ivec2 size = ivec2(pc.width, pc.height);
    const vec4 receiver = texelFetch(receivers, ivec2(g), 0);
    if (!(receiver.w > 0.0)) {
        imageStore(irradiance, ivec2(g), vec4(0.0));
        return;
    }
    const CameraRays rays = camera_rays(vec2(size));
    const vec3 normal = receiver.xyz;
    const vec3 point = rays.eye + receiver.w * normalize(camera_ray(rays, vec2(g) + 0.5));
    const float h = dot(point - rays.eye, normal);
    vec3 e = level_flux(0u, size, ivec2(g)) / max(camera_level_pixel_area(rays, ivec2(g), 0, normal, h), 1e-30);
    for (int level = 1; level < kCameraCausticLevels; ++level) {
        const ivec2 level_size = ivec2(camera_level_size(uvec2(size), level));
        const uint base = camera_level_offset(uvec2(size), level);
        const vec2 c = (vec2(g) + 0.5) / float(1 << level) - 0.5;
        const vec2 corner = floor(c);
        const vec2 f = c - corner;
        vec3 sum = vec3(0.0);
        float weights = 0.0;
        for (int k = 0; k < 4; ++k) {
            const ivec2 step = ivec2(k & 1, k >> 1);
            const ivec2 t = ivec2(corner) + step;
            if (any(lessThan(t, ivec2(0))) || any(greaterThanEqual(t, level_size))) continue;
            const ivec2 texel = camera_level_texel(t, level, size);
            if (!receiver_on_plane(rays, texel, texelFetch(receivers, texel, 0), point, normal)) continue;
            const float area = camera_level_pixel_area(rays, t, level, normal, h);
            if (!(area > 0.0)) continue;
            const float w = max((step.x == 1 ? f.x : 1.0 - f.x) * (step.y == 1 ? f.y : 1.0 - f.y), 1e-4);
            sum += w * level_flux(base, level_size, t) / area;
            weights += w;
        }
        if (weights > 0.0) e += sum / weights;
    }
    imageStore(irradiance, ivec2(g), vec4(e, receiver.w));
}
